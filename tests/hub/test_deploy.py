"""deploy/: the hub configuration for one server loads in JupyterHub's own loader and
gives each learner the domain labkit.teacher.domain gives; the Zero to JupyterHub values
compute the same domains; the image's entry point copies the book into the home and
keeps a learner's edits; the Dockerfile is what KubeSpawner/DockerSpawner expect."""
import os
import subprocess
import sys
from pathlib import Path
from types import SimpleNamespace

import yaml
from traitlets.config import Config, PyFileConfigLoader

from labkit.teacher.domain import domain_for

REPO = Path(__file__).resolve().parents[2]
DEPLOY = REPO / "deploy"


def _spawner(name, uid):
    return SimpleNamespace(user=SimpleNamespace(name=name, id=uid))


def _load_hub_config(monkeypatch, **env):
    for key, value in env.items():
        monkeypatch.setenv(key, value)
    loader = PyFileConfigLoader("jupyterhub_config.py", path=str(DEPLOY))
    return loader.load_config()


def test_one_server_config(monkeypatch):
    monkeypatch.delenv("LABKIT_CLASS_DOMAIN", raising=False)
    c = _load_hub_config(monkeypatch, LABKIT_CLASS="ann ben", LABKIT_TEACHERS="tea")
    assert c.Authenticator.allowed_users == {"ann", "ben"}
    assert c.Authenticator.admin_users == {"tea"}
    assert c.JupyterHub.hub_bind_url == "http://127.0.0.1:8081"
    env = c.Spawner.environment
    assert [env["ROS_DOMAIN_ID"](_spawner("ann", i)) for i in (1, 2, 101, 102)] == \
        ["1", "2", "101", "1"]
    assert env["LABKIT_LEARNER"](_spawner("ann", 1)) == "ann"
    assert env["LABKIT_TIME"] == "live"
    culler = c.JupyterHub.services[0]
    assert culler["name"] == "idle-culler" and "--timeout=3600" in culler["command"]
    assert set(c.JupyterHub.load_roles[0]["scopes"]) >= {"delete:servers", "read:users:activity"}
    shared = _load_hub_config(monkeypatch, LABKIT_CLASS_DOMAIN="7")
    assert shared.Spawner.environment["ROS_DOMAIN_ID"](_spawner("ben", 40)) == "7"


def test_z2jh_values_same_domains(monkeypatch):
    values = yaml.safe_load((DEPLOY / "z2jh-values.yaml").read_text(encoding="utf-8"))
    assert values["singleuser"]["uid"] == 1000
    assert values["cull"]["enabled"] is True
    c = Config()
    c.KubeSpawner.environment = {}
    code = values["hub"]["extraConfig"]["labkit-domain"]
    monkeypatch.delenv("LABKIT_CLASS_DOMAIN", raising=False)
    exec(code, {"c": c})
    fn = c.KubeSpawner.environment["ROS_DOMAIN_ID"]
    for uid in range(1, 250):
        assert fn(_spawner("x", uid)) == str(domain_for("x", uid))
    monkeypatch.setenv("LABKIT_CLASS_DOMAIN", "9")
    assert fn(_spawner("x", 3)) == "9"


def test_dockerfile_fits_kubespawner_and_dockerspawner():
    text = (DEPLOY / "Dockerfile").read_text(encoding="utf-8")
    lines = [ln.strip() for ln in text.splitlines() if ln.strip() and not ln.startswith("#")]
    assert "ARG NB_UID=1000" in lines and "USER ${NB_UID}" in lines
    assert "EXPOSE 8888" in lines
    assert lines[-1] == 'CMD ["jupyterhub-singleuser"]'
    assert 'pip install -c requirements.lock -e ".[lab]"' in text          # as `make lab`
    assert "-c requirements-hub.lock jupyterhub" in text


def test_entry_point_copies_the_book_and_keeps_edits(tmp_path):
    home = tmp_path / "jovyan"
    (home / "book" / "part1_basics").mkdir(parents=True)
    mine = home / "book" / "part1_basics" / "ch03_topics.ipynb"
    mine.write_text("my own edits\n", encoding="utf-8")
    env = dict(os.environ, HOME=str(home), PYTHONPATH=str(REPO),
               PATH=os.path.dirname(sys.executable) + os.pathsep + os.environ["PATH"])
    env.pop("JUPYTER_CONFIG_DIR", None)
    res = subprocess.run(["sh", str(DEPLOY / "labkit-start"), "sh", "-c", "echo started $HOME"],
                         env=env, capture_output=True, text=True, timeout=120)
    assert res.returncode == 0, res.stderr
    assert res.stdout == f"started {home}\n"
    assert (home / "book" / "_toc.yml").is_file()
    assert (home / "book" / "part1_basics" / "ch02_nodes.ipynb").is_file()
    assert mine.read_text(encoding="utf-8") == "my own edits\n"
    # labkit's custom.css (wide SVG pictures fit their cell) in the learner's config dir
    assert ".jp-RenderedSVG img" in (home / ".jupyter" / "custom" / "custom.css").read_text(
        encoding="utf-8")
