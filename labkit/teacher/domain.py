"""One ROS domain per learner, so that learners on one host or one network never see
each other's DDS traffic (`labkit exec`, `labkit ros2`, `labkit.connect()`).

ROS 2 on Linux allows domain ids 0-101 (above 101 the ports of a participant reach the
kernel's ephemeral range; 0 is every machine's default). A learner gets 1-101:

* from the hub's user id when the hub gives one (``1 + (id - 1) % 101``: the first 101
  learners of a hub get different domains, whatever their names), else
* from the user name (``1 + sha256(name) % 101``: stable across hubs, may collide).

``LABKIT_CLASS_DOMAIN`` set on the hub (0-101) puts the whole class on that one domain
(a teacher's demo). The hub's configuration (deploy/jupyterhub_config.py) sets the
result as ROS_DOMAIN_ID in each learner's environment.
"""
from __future__ import annotations

import hashlib

MAX_DOMAIN = 101            # ROS 2 on Linux: 0-101
CLASS_ENV = "LABKIT_CLASS_DOMAIN"


def domain_for(name: str | None = None, user_id: int | None = None,
               class_domain: str | int | None = None) -> int:
    """The ROS_DOMAIN_ID of a learner (see the module doc)."""
    if class_domain not in (None, ""):
        value = int(str(class_domain).strip())
        if not 0 <= value <= MAX_DOMAIN:
            raise ValueError(f"{CLASS_ENV} must be within 0-{MAX_DOMAIN}, got {value}")
        return value
    if user_id is not None:
        if int(user_id) < 1:
            raise ValueError(f"a hub user id starts at 1, got {user_id}")
        return 1 + (int(user_id) - 1) % MAX_DOMAIN
    if not name:
        raise ValueError("a learner needs a name or a hub user id")
    digest = hashlib.sha256(name.encode("utf-8")).digest()
    return 1 + int.from_bytes(digest[:8], "big") % MAX_DOMAIN


def spawner_environment(spawner) -> dict:
    """The environment a JupyterHub spawner adds for one learner (used as
    ``c.Spawner.environment`` callables and by ``pre_spawn_hook``)."""
    import os
    user = spawner.user
    domain = domain_for(user.name, getattr(user, "id", None), os.environ.get(CLASS_ENV))
    return {"ROS_DOMAIN_ID": str(domain), "LABKIT_LEARNER": user.name}


def main(argv=None) -> int:
    """`labkit teacher domain NAME... [--id N]`: the domain each learner gets."""
    import argparse
    import os
    parser = argparse.ArgumentParser(prog="labkit teacher domain")
    parser.add_argument("names", nargs="+")
    args = parser.parse_args(argv)
    for name in args.names:
        print(f"{name}\t{domain_for(name, None, os.environ.get(CLASS_ENV))}")
    return 0
