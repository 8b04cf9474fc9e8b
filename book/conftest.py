"""nbval runs every notebook here in virtual time: deterministic outputs.
(The kernels nbval starts inherit this environment; `make test` sets it too.)"""
import os

os.environ.setdefault("LABKIT_TIME", "virtual")
os.environ.setdefault("TZ", "UTC")      # dates printed by tools do not depend on the machine
