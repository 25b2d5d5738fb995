"""The exceptions of the sloshsph module.

Each corresponds to an exit code of the ``sloshsph`` program (README.md): ``CaseError`` to 2 (bad
case, bad key, bad run directory), ``RunFailed`` to 3 (the simulation failed), ``Interrupted`` to 4
(SIGINT/SIGTERM: the run directory is consistent and resumable).
"""


class CaseError(ValueError):
    """A bad case, key, value, record file or run directory: what ``sloshsph`` reports with exit 2.

    ``str(error)`` is exactly the message the program prints after ``sloshsph: error:``.

    Attributes:
        where: ``"file:line"``, a file, ``"--set"`` or a directory ("" when unknown).
        key: the dotted case key (``"time.dt"``), "" when the error has none.
        message: the message without ``where`` and ``key``.
    """

    def __init__(self, text, where="", key="", message=None):
        super().__init__(text)
        self.where = where
        self.key = key
        self.message = text if message is None else message


class RunFailed(RuntimeError):
    """The simulation failed after it started (non-finite values, leaks...): exit 3.

    Attributes:
        result: the ``Run`` (or ``Sweep``) whose outputs hold the last good state.
    """

    def __init__(self, text, result=None):
        super().__init__(text)
        self.result = result


class Interrupted(KeyboardInterrupt):
    """SIGINT (Ctrl-C) or SIGTERM stopped a run: exit 4.

    A ``KeyboardInterrupt``, so that a script stops as it would on Ctrl-C anywhere else. The run
    stopped after its current step and wrote consistent outputs and a checkpoint:
    ``sloshsph.resume(error.result.path)`` continues it with the same results as an unbroken run.

    Attributes:
        result: the ``Run`` (or ``Sweep``), or None when the run was stopped before it had
            written anything (while the fluid settled).
    """

    def __init__(self, text, result=None):
        super().__init__(text)
        self.result = result
