"""Pictures: every view has a live face (a widget in JupyterLab) and a static face
(PNG/SVG/HTML stored in the notebook for the HTML book)."""
