"""Turning 'str | Substitution | list of them' into text (launch.utilities)."""
from labkit.launch.substitution import Substitution


def normalize_to_list_of_substitutions(value):
    from labkit.launch.substitutions import TextSubstitution
    if value is None:
        return []
    if isinstance(value, (str, Substitution)):
        value = [value]
    result = []
    for item in value:
        if isinstance(item, str):
            result.append(TextSubstitution(text=item))
        elif isinstance(item, Substitution):
            result.append(item)
        else:
            raise TypeError(
                "Failed to normalize given item of type '{}', when only 'str' or "
                "'launch.Substitution' were expected.".format(type(item)))
    return result


def perform_substitutions(context, subs):
    return ''.join(context.perform_substitution(s) for s in subs)


def perform(context, value):
    """str, Substitution, or a list of them -> text."""
    return perform_substitutions(context, normalize_to_list_of_substitutions(value))


def is_a_substitution(value):
    if isinstance(value, Substitution):
        return True
    return isinstance(value, (list, tuple)) and any(isinstance(v, Substitution) for v in value)
