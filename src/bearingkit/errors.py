"""Exception types shared by every layer."""


class InputError(ValueError):
    """Bad input: the message is one line naming the field, the value and what was expected."""


class ConvergenceError(RuntimeError):
    """A single interactive solve that did not converge; ``result`` carries the diagnostics."""

    def __init__(self, message: str, result=None):
        super().__init__(message)
        self.result = result
