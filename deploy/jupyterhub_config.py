"""JupyterHub for a class on ONE Linux server (JupyterHub 6, requirements-hub.lock).

Each learner is a Linux user (PAM login, the machine's own accounts) whose Jupyter
server runs as a systemd unit with memory/CPU limits (SystemdSpawner) or, without
systemd-spawner installed, as a local process of that user (LocalProcessSpawner).
Each learner gets their own ROS domain (labkit.teacher.domain: 1-101 from the hub's
user id); LABKIT_CLASS_DOMAIN=N in the hub's environment puts the class on domain N.
jupyterhub-idle-culler stops servers idle for an hour.

    sudo /opt/labkit/.venv/bin/jupyterhub -f deploy/jupyterhub_config.py

Put TLS in front (a reverse proxy, or c.JupyterHub.ssl_cert/ssl_key below) before
learners type passwords over a network.
"""
import os
import shutil
import sys

from labkit.teacher.domain import CLASS_ENV, domain_for

c = get_config()  # noqa: F821  (provided by JupyterHub's config loader)

# -- where the hub listens: the proxy on the server's public port, the hub itself local
c.JupyterHub.bind_url = os.environ.get("LABKIT_HUB_URL", "http://:8000")
c.JupyterHub.hub_bind_url = "http://127.0.0.1:8081"
c.JupyterHub.db_url = "sqlite:////srv/jupyterhub/jupyterhub.sqlite"
c.JupyterHub.cookie_secret_file = "/srv/jupyterhub/jupyterhub_cookie_secret"
# c.JupyterHub.ssl_cert = "/etc/ssl/certs/hub.pem"
# c.JupyterHub.ssl_key = "/etc/ssl/private/hub.key"

# -- who may log in: the class list (Linux accounts); the teacher is the admin
c.JupyterHub.authenticator_class = "pam"
c.Authenticator.allowed_users = set(
    os.environ.get("LABKIT_CLASS", "").split()) or {"learner1", "learner2"}
c.Authenticator.admin_users = set(os.environ.get("LABKIT_TEACHERS", "teacher").split())

# -- each learner's server: as that Linux user, JupyterLab, the book in ~/book
try:
    import systemdspawner  # noqa: F401
    c.JupyterHub.spawner_class = "systemdspawner.SystemdSpawner"
    c.SystemdSpawner.mem_limit = "2G"          # one learner needs about 0.5 GB (teacher's page)
    c.SystemdSpawner.cpu_limit = 1.0
    c.SystemdSpawner.isolate_tmp = True        # a private /tmp per learner
    c.SystemdSpawner.isolate_devices = True
    c.SystemdSpawner.disable_user_sudo = True
    c.SystemdSpawner.unit_name_template = "jupyter-{USERNAME}"
except ImportError:
    c.JupyterHub.spawner_class = "jupyterhub.spawner.LocalProcessSpawner"
c.Spawner.cmd = [os.path.join(os.path.dirname(sys.executable), "jupyterhub-singleuser")]
c.Spawner.default_url = "/lab/tree/book/intro.md"
c.Spawner.notebook_dir = "~"
c.Spawner.args = ["--ContentsManager.pre_save_hook=labkit.tools.lab.strip_live_views",
                  "--LabApp.custom_css=True"]     # labkit's custom.css (labkit-start installs it)


def _environment(spawner):
    user = spawner.user
    domain = domain_for(user.name, user.id, os.environ.get(CLASS_ENV))
    return str(domain)


c.Spawner.environment = {
    "ROS_DOMAIN_ID": _environment,          # each learner their own DDS domain
    "LABKIT_LEARNER": lambda spawner: spawner.user.name,
    "LABKIT_TIME": "live",                  # as `labkit lab`
    "LABKIT_NO_WINDOW": "1",                # no browser window opened on the server
    "TZ": "UTC",
}


async def _copy_book(spawner):
    """The book's files a learner's ~/book lacks (their own edits stay)."""
    import pwd
    from pathlib import Path

    from labkit.tools import lab
    try:
        home = Path(pwd.getpwnam(spawner.user.name).pw_dir)
    except KeyError:
        return
    target = home / "book"
    lab.working_copy(lab.BOOK, target)
    uid = pwd.getpwnam(spawner.user.name).pw_uid
    gid = pwd.getpwnam(spawner.user.name).pw_gid
    for path in [target, *target.rglob("*")]:
        if path.stat().st_uid != uid:
            shutil.chown(path, uid, gid)


c.Spawner.pre_spawn_hook = _copy_book

# -- stop servers idle for an hour (a stopped server keeps every file in the home)
c.JupyterHub.load_roles = [{
    "name": "idle-culler",
    "scopes": ["list:users", "read:users:activity", "read:servers", "delete:servers"],
    "services": ["idle-culler"],
}]
c.JupyterHub.services = [{
    "name": "idle-culler",
    "command": [sys.executable, "-m", "jupyterhub_idle_culler", "--timeout=3600"],
}]
