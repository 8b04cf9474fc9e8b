"""Learners' copies of ch03 for the hub and grading tests: as shipped (every exercise
still a TODO stub) and solved (each stub replaced by the book's reference answer)."""
import json
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
CH03 = REPO / "book" / "part1_basics" / "ch03_topics.ipynb"


def load(path=CH03) -> dict:
    return json.loads(Path(path).read_text(encoding="utf-8"))


def solved(nb: dict) -> dict:
    """Each exercise's TODO stub replaced by its reference answer (cells tagged solution);
    3.3's stub is the listener itself, its answer the fixed QoS line."""
    nb = json.loads(json.dumps(nb))
    cells = nb["cells"]
    for i, cell in enumerate(cells):
        if "solution" not in cell.get("metadata", {}).get("tags", []):
            continue
        for j in range(i - 1, -1, -1):
            src = "".join(cells[j]["source"])
            if cells[j]["cell_type"] == "code" and src.lstrip().startswith("# TODO"):
                cells[j]["source"] = cells[i]["source"]
                break
    for cell in cells:
        src = "".join(cell["source"])
        if cell["cell_type"] == "code" and "qos = 10          # TODO" in src:
            cell["source"] = src.replace("qos = 10          # TODO", "qos = qos_profile_sensor_data  #")
    return nb


def write(nb: dict, path: Path) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(nb, ensure_ascii=False, indent=1) + "\n", encoding="utf-8")
    return path
