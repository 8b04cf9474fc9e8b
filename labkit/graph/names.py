"""ROS 2 name rules: validation (rmw/rcl), expansion and hidden names.

Each validator returns None when the name is valid, else (error_msg, invalid_index),
with the texts rmw/rcl use, so rclpy's exceptions can show them.
"""
from functools import lru_cache

TOPIC_MAX_NAME_LENGTH = 255 - 8
NODE_NAME_MAX_LENGTH = 255
NAMESPACE_MAX_LENGTH = TOPIC_MAX_NAME_LENGTH - 2


def _alnum(c):
    return ("a" <= c <= "z") or ("A" <= c <= "Z") or ("0" <= c <= "9")


def _digit(c):
    return "0" <= c <= "9"


@lru_cache(maxsize=4096)
def validate_node_name(name):
    if not name:
        return "node name must not be empty", 0
    for i, c in enumerate(name):
        if not (_alnum(c) or c == "_"):
            return "node name must not contain characters other than alphanumerics or '_'", i
    if _digit(name[0]):
        return "node name must not start with a number", 0
    if len(name) > NODE_NAME_MAX_LENGTH:
        return "node name length should not exceed '255'", NODE_NAME_MAX_LENGTH - 1
    return None


@lru_cache(maxsize=4096)
def validate_full_topic_name(name):
    n = len(name)
    if n == 0:
        return "topic name must not be empty", 0
    if name[0] != "/":
        return "topic name must be absolute, it must lead with a '/'", 0
    if name[-1] == "/":
        return "topic name must not end with a '/'", n - 1
    for i, c in enumerate(name):
        if not (_alnum(c) or c in "_/"):
            return ("topic name must not contain characters other than alphanumerics, "
                    "'_', or '/'", i)
    for i in range(n - 1):
        if name[i] == "/":
            if name[i + 1] == "/":
                return "topic name must not contain repeated '/'", i + 1
            if _digit(name[i + 1]):
                return "topic name must not have a token that starts with a number", i + 1
    if n > TOPIC_MAX_NAME_LENGTH:
        return "topic length should not exceed '255U - 8U'", TOPIC_MAX_NAME_LENGTH - 1
    return None


_NAMESPACE_TEXTS = {
    "topic name must not be empty": "namespace must not be empty",
    "topic name must be absolute, it must lead with a '/'":
        "namespace must be absolute, it must lead with a '/'",
    "topic name must not end with a '/'": "namespace must not end with a '/', unless only a '/'",
    "topic name must not contain characters other than alphanumerics, '_', or '/'":
        "namespace must not contain characters other than alphanumerics, '_', or '/'",
    "topic name must not contain repeated '/'": "namespace must not contain repeated '/'",
    "topic name must not have a token that starts with a number":
        "namespace must not have a token that starts with a number",
}


@lru_cache(maxsize=4096)
def validate_namespace(namespace):
    if namespace == "/":
        return None
    result = validate_full_topic_name(namespace)
    if result is not None and not result[0].startswith("topic length"):
        return _NAMESPACE_TEXTS[result[0]], result[1]
    if len(namespace) > NAMESPACE_MAX_LENGTH:
        return "namespace should not exceed '255U - 8U - 2U'", NAMESPACE_MAX_LENGTH - 1
    return None


@lru_cache(maxsize=4096)
def validate_topic_name(name):
    """rcl_validate_topic_name: a (possibly relative, ~ or {sub}) topic or service name."""
    n = len(name)
    if n == 0:
        return "topic name must not be empty string", 0
    if _digit(name[0]):
        return "topic name token must not start with a number", 0
    if name[-1] == "/":
        return "topic name must not end with a forward slash", n - 1
    in_brace = False
    brace_at = 0
    sub_bad = "substitution name must not contain characters other than alphanumerics or '_'"
    for i, c in enumerate(name):
        if _alnum(c):
            if _digit(c) and in_brace and i > 0 and i - 1 == brace_at:
                return "substitution name must not start with a number", i
        elif c == "_":
            pass
        elif c == "/":
            if in_brace:
                return sub_bad, i
        elif c == "~":
            if i != 0:
                return "topic name must not have tilde '~' unless it is the first character", i
        elif c == "{":
            brace_at = i
            if in_brace:
                return sub_bad, i
            in_brace = True
        elif c == "}":
            if not in_brace:
                return "topic name must not have unmatched (unbalanced) curly braces '{}'", i
            in_brace = False
        else:
            if in_brace:
                return sub_bad, i
            return ("topic name must not contain characters other than alphanumerics, "
                    "'_', '~', '{', or '}'", i)
    if in_brace:
        return "topic name must not have unmatched (unbalanced) curly braces '{}'", brace_at
    for i in range(n - 1):
        if name[i] == "/":
            if _digit(name[i + 1]):
                return "topic name token must not start with a number", i + 1
        elif i == 1 and name[0] == "~":
            return ("topic name must not have a tilde '~' that is not followed by a "
                    "forward slash '/'", 1)
    return None


class ExpansionError(ValueError):
    pass


def expand_topic_name(name, node_name, namespace, substitutions=None):
    if substitutions:
        return _expand(name, node_name, namespace, tuple(sorted(substitutions.items())))
    return _expand(name, node_name, namespace, ())


@lru_cache(maxsize=4096)
def _expand(name, node_name, namespace, substitutions):
    """rcl_expand_topic_name: relative, '~' and '{node}'/'{ns}'/'{namespace}' -> absolute."""
    if not name:
        raise ExpansionError("topic name must not be empty string")
    is_absolute = name[0] == "/"
    out = name
    if name[0] == "~":
        base = namespace if namespace != "/" else ""
        out = base + "/" + node_name + name[1:]
        is_absolute = True
    if "{" in out:
        subs = {"node": node_name, "ns": namespace, "namespace": namespace}
        subs.update(dict(substitutions))
        pieces = []
        i = 0
        while i < len(out):
            c = out[i]
            if c == "{":
                j = out.find("}", i)
                if j < 0:
                    raise ExpansionError("unmatched curly brace")
                key = out[i + 1:j]
                if key not in subs:
                    raise ExpansionError(f"unknown substitution: {{{key}}}")
                pieces.append(subs[key])
                i = j + 1
            else:
                pieces.append(c)
                i += 1
        out = "".join(pieces)
        # a substitution of '/' (root namespace) can double a slash
        while "//" in out:
            out = out.replace("//", "/")
        if out.startswith("/"):
            is_absolute = True
    if not is_absolute:
        out = (namespace if namespace != "/" else "") + "/" + out
    return out


def is_hidden(name):
    """A topic, service or node name is hidden when any token starts with '_'."""
    return any(tok.startswith("_") for tok in name.split("/"))


def normalize_namespace(namespace):
    """rcl_node_init: '' -> '/', 'ns' -> '/ns'."""
    if not namespace:
        return "/"
    if namespace[0] != "/":
        return "/" + namespace
    return namespace


def fully_qualified_node_name(namespace, node_name):
    return (namespace.rstrip("/") if namespace != "/" else "") + "/" + node_name
