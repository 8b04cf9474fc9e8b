"""rmw's QoS compatibility rules, on plain policy values (rmw/types.h numbering)."""
OK, WARNING, ERROR = 0, 1, 2
# QoSPolicyKind bits
DURABILITY, DEADLINE, LIVELINESS, RELIABILITY = 1 << 1, 1 << 2, 1 << 3, 1 << 4
RELIABLE, BEST_EFFORT = 1, 2
TRANSIENT_LOCAL, VOLATILE = 1, 2
AUTOMATIC, MANUAL_BY_TOPIC = 1, 3
_INFINITE = (0, 2**63 - 1)


def check_compatible(pub, sub):
    """(OK|WARNING|ERROR, reason, last incompatible policy kind or None)."""
    errors = []
    if pub.reliability == BEST_EFFORT and sub.reliability == RELIABLE:
        errors.append(('ERROR: Best effort publisher and reliable subscription;', RELIABILITY))
    if pub.durability == VOLATILE and sub.durability == TRANSIENT_LOCAL:
        errors.append(('ERROR: Volatile publisher and transient local subscription;',
                       DURABILITY))
    pub_dl, sub_dl = pub.deadline.nanoseconds, sub.deadline.nanoseconds
    if sub_dl not in _INFINITE and pub_dl in _INFINITE:
        errors.append(('ERROR: Subscription has a deadline, but publisher does not;', DEADLINE))
    elif sub_dl not in _INFINITE and pub_dl > sub_dl:
        errors.append(('ERROR: Subscription deadline is less than publisher deadline;',
                       DEADLINE))
    if pub.liveliness == AUTOMATIC and sub.liveliness == MANUAL_BY_TOPIC:
        errors.append(("ERROR: Publisher's liveliness is automatic and subscription's is "
                       "manual by topic;", LIVELINESS))
    if errors:
        return ERROR, ''.join(e[0] for e in errors), errors[-1][1]
    unsure = [p for p in (pub.reliability, sub.reliability, pub.durability, sub.durability)
              if p in (0, 3)]
    if unsure:
        return WARNING, 'WARNING: a policy is system default or unknown;', None
    return OK, '', None
