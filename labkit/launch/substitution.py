"""The base of every substitution: something that becomes text when the launch runs."""


class Substitution:
    def describe(self):
        return repr(self)

    def perform(self, context):
        raise NotImplementedError


class SubstitutionFailure(RuntimeError):
    pass
