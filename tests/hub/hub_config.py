"""JupyterHub configuration of tests/hub/test_hub.py: loopback only, three learners with
their own passwords (a small authenticator), local processes (SimpleLocalProcessSpawner),
each learner's ROS domain from labkit.teacher.domain (as deploy/jupyterhub_config.py),
and jupyterhub-idle-culler with a short timeout. Read from HUBTEST_* variables."""
import json
import os
import sys

from jupyterhub.auth import Authenticator
from traitlets import Dict

from labkit.teacher.domain import spawner_environment

c = get_config()  # noqa: F821  (JupyterHub's config loader provides it)
here = os.environ["HUBTEST_DIR"]


class ClassListAuthenticator(Authenticator):
    """A learner logs in with the password of the class list, nothing else."""
    passwords = Dict(config=True)

    async def authenticate(self, handler, data):
        name = (data or {}).get("username")
        if name in self.passwords and data.get("password") == self.passwords[name]:
            return name
        return None


c.JupyterHub.authenticator_class = ClassListAuthenticator
c.ClassListAuthenticator.passwords = json.loads(os.environ["HUBTEST_PASSWORDS"])
c.Authenticator.allowed_users = set(c.ClassListAuthenticator.passwords)
c.Authenticator.admin_users = set()

c.JupyterHub.bind_url = f"http://127.0.0.1:{os.environ['HUBTEST_PORT']}"
c.JupyterHub.hub_bind_url = f"http://127.0.0.1:{os.environ['HUBTEST_HUB_PORT']}"
c.ConfigurableHTTPProxy.api_url = f"http://127.0.0.1:{os.environ['HUBTEST_PROXY_API_PORT']}"
c.ConfigurableHTTPProxy.command = [os.environ["HUBTEST_CHP"]]
c.JupyterHub.db_url = f"sqlite:///{here}/jupyterhub.sqlite"
c.JupyterHub.cookie_secret_file = f"{here}/jupyterhub_cookie_secret"
c.JupyterHub.pid_file = f"{here}/jupyterhub.pid"
c.JupyterHub.last_activity_interval = 2
c.JupyterHub.tornado_settings = {"slow_spawn_timeout": 0}   # start all three at once

c.JupyterHub.spawner_class = "jupyterhub.spawner.SimpleLocalProcessSpawner"
c.SimpleLocalProcessSpawner.home_dir_template = f"{here}/home/{{username}}"
c.Spawner.ip = "127.0.0.1"
c.Spawner.cmd = [os.path.join(os.path.dirname(sys.executable), "jupyterhub-singleuser")]
c.Spawner.args = ["--allow-root"] if os.geteuid() == 0 else []
c.Spawner.start_timeout = 120
c.Spawner.http_timeout = 120
c.Spawner.environment = {
    "ROS_DOMAIN_ID": lambda spawner: spawner_environment(spawner)["ROS_DOMAIN_ID"],
    "LABKIT_LEARNER": lambda spawner: spawner.user.name,
    "LABKIT_TIME": os.environ.get("HUBTEST_TIME", "virtual"),   # benchmarks: live
    "LABKIT_NO_WINDOW": "1",
    "LABKIT_EXERCISE_LOG": lambda spawner: f"{spawner.home_dir}/.labkit_exercises.jsonl",
    "TZ": "UTC",
    "JUPYTER_CONFIG_DIR": lambda spawner: f"{spawner.home_dir}/.jupyter",
    "JUPYTER_DATA_DIR": lambda spawner: f"{spawner.home_dir}/.local/share/jupyter",
    "JUPYTER_RUNTIME_DIR": lambda spawner: f"{spawner.home_dir}/.local/share/jupyter/runtime",
    "IPYTHONDIR": lambda spawner: f"{spawner.home_dir}/.ipython",
}
if os.environ.get("HUBTEST_CLASS_DOMAIN"):
    c.Spawner.environment["ROS_DOMAIN_ID"] = os.environ["HUBTEST_CLASS_DOMAIN"]

c.JupyterHub.load_roles = [{
    "name": "idle-culler",
    "scopes": ["list:users", "read:users:activity", "read:servers", "delete:servers"],
    "services": ["idle-culler"],
}]
c.JupyterHub.services = [{
    "name": "idle-culler",
    "command": [sys.executable, "-m", "jupyterhub_idle_culler",
                f"--timeout={os.environ.get('HUBTEST_IDLE_TIMEOUT', '15')}", "--cull-every=3"],
}]
