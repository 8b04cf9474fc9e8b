"""tools/longest_run.py: the measure of code shared with the official tutorials."""
import importlib.util
import json
import os

HERE = os.path.dirname(os.path.abspath(__file__))
spec = importlib.util.spec_from_file_location(
    "longest_run", os.path.join(HERE, "..", "..", "tools", "longest_run.py"))
longest_run = importlib.util.module_from_spec(spec)
spec.loader.exec_module(longest_run)


def test_finds_the_whole_shared_run_through_indentation(tmp_path):
    shared = "def generate(self):\n    return [a for a in range(10) if a % 3 == 0]  # keep every third one\n"
    ref = tmp_path / "ref"
    ref.mkdir()
    # the reference has it indented inside an .rst code block
    (ref / "page.rst").write_text("Intro\n\n.. code-block:: python\n\n" +
                                  "".join("    " + line + "\n" for line in shared.splitlines()))
    ours = tmp_path / "ours.py"
    ours.write_text("import os\n\n" + shared + "\nprint('ours')\n")
    nb = tmp_path / "book.ipynb"
    nb.write_text(json.dumps({"cells": [
        {"cell_type": "markdown", "source": [shared]},          # prose is not code
        {"cell_type": "code", "source": ["x = 1\n", "y = 2\n"]}]}))
    assert longest_run.main(["--ref", str(ref), "--limit", "200", str(ours), str(nb)]) == 0
    texts = longest_run.our_texts([str(ours), str(nb)])
    assert [label.rsplit("/", 1)[-1] for label, _ in texts] == ["ours.py", "book.ipynb cell 1"]
    squeezed = [(label, longest_run.squeeze(text)) for label, text in texts]
    refs = [(n, longest_run.squeeze(t)) for n, t in longest_run.reference_files([str(ref)])]
    best = longest_run.longest_runs(squeezed, refs)
    assert list(best) == [str(ours)]
    assert len(longest_run.squeeze(shared)) <= best[str(ours)][0] <= len(longest_run.squeeze(shared)) + 2
    # the same run counted exactly is cut by the indentation
    exact = longest_run.longest_runs(texts, list(longest_run.reference_files([str(ref)])))
    assert exact[str(ours)][0] < len(shared)
    assert longest_run.main(["--ref", str(ref), "--limit", "60", str(ours)]) == 1


def test_import_lines_can_be_left_out(tmp_path):
    imports = ("from launch import LaunchDescription\nfrom launch.actions import "
               "DeclareLaunchArgument, IncludeLaunchDescription, TimerAction\n"
               "from launch.substitutions import LaunchConfiguration, PathJoinSubstitution\n")
    ref = tmp_path / "ref"
    ref.mkdir()
    (ref / "theirs.py").write_text(imports + "\n\ndef theirs():\n    return 1\n")
    ours = tmp_path / "ours.py"
    ours.write_text(imports + "\n\ndef ours():\n    return 2\n")
    assert longest_run.main(["--ref", str(ref), "--limit", "150", str(ours)]) == 1
    assert longest_run.main(["--ref", str(ref), "--limit", "150", "--skip-imports",
                             str(ours)]) == 0
    assert "import" not in longest_run.without_imports(imports).strip()
