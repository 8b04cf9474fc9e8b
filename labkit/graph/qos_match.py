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
    warnings = _warnings(pub, sub)
    if warnings:
        return WARNING, ''.join(warnings), None
    return OK, '', None


_RELIABILITY_STR = {0: 'system_default', 1: 'reliable', 2: 'best_effort', 3: 'unknown'}
_DURABILITY_STR = {0: 'system_default', 1: 'transient_local', 2: 'volatile', 3: 'unknown'}
_LIVELINESS_STR = {0: 'system_default', 1: 'automatic', 3: 'manual_by_topic', 4: 'unknown'}
_UNSURE_RD = (0, 3)        # system_default, unknown
_UNSURE_LIVELINESS = (0, 4)


def _warnings(pub, sub):
    """rmw_dds_common's warnings when a policy is system default or unknown."""
    out = []
    pr, sr = pub.reliability, sub.reliability
    if pr in _UNSURE_RD and sr in _UNSURE_RD:
        out.append(f'WARNING: Publisher reliability is {_RELIABILITY_STR[pr]} and '
                   f'subscription reliability is {_RELIABILITY_STR[sr]};')
    elif pr in _UNSURE_RD and sr == RELIABLE:
        out.append(f'WARNING: Reliable subscription, but publisher is {_RELIABILITY_STR[pr]};')
    elif pr == BEST_EFFORT and sr in _UNSURE_RD:
        out.append(f'WARNING: Best effort publisher, but subscription is {_RELIABILITY_STR[sr]};')
    pd, sd = pub.durability, sub.durability
    if pd in _UNSURE_RD and sd in _UNSURE_RD:
        # (sic) rmw_dds_common spells it "durabilty" here
        out.append(f'WARNING: Publisher durabilty is {_DURABILITY_STR[pd]} and '
                   f'subscription durability is {_DURABILITY_STR[sd]};')
    elif pd in _UNSURE_RD and sd == TRANSIENT_LOCAL:
        out.append(f'WARNING: Transient local subscription, but publisher is {_DURABILITY_STR[pd]};')
    elif pd == VOLATILE and sd in _UNSURE_RD:
        out.append(f'WARNING: Volatile publisher, but subscription is {_DURABILITY_STR[sd]};')
    pl, sl = pub.liveliness, sub.liveliness
    if pl in _UNSURE_LIVELINESS and sl in _UNSURE_LIVELINESS:
        out.append(f'WARNING: Publisher liveliness is {_LIVELINESS_STR.get(pl, "unknown")} and '
                   f'subscription liveliness is {_LIVELINESS_STR.get(sl, "unknown")};')
    elif pl in _UNSURE_LIVELINESS and sl == MANUAL_BY_TOPIC:
        out.append("WARNING: Subscription's liveliness is manual by topic, but publisher's is "
                   f'{_LIVELINESS_STR.get(pl, "unknown")};')
    elif pl == AUTOMATIC and sl in _UNSURE_LIVELINESS:
        out.append("WARNING: Publisher's liveliness is automatic, but subscription's is "
                   f'{_LIVELINESS_STR.get(sl, "unknown")};')
    return out
