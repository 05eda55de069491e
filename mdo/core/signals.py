"""Signals as interrupts: SIGINT and SIGTERM both stop a run like Ctrl-C, and the
exception says which one came, wherever it lands (inside IPOPT's iterations, while a
run folder is written, between stages), so the exit code is 130 for SIGINT and 143
for SIGTERM (128 + signal number, what a shell reports)."""
import signal

__all__ = ["SignalInterrupt", "raise_interrupt", "interrupt_signal", "exit_code"]


class SignalInterrupt(KeyboardInterrupt):
    """KeyboardInterrupt raised by a signal handler; ``signum`` is the signal."""

    def __init__(self, signum: int):
        super().__init__(signal.Signals(signum).name)
        self.signum = int(signum)


def raise_interrupt(signum, frame):
    """A signal handler: raise :class:`SignalInterrupt` for ``signum``."""
    raise SignalInterrupt(signum)


def interrupt_signal(exc: BaseException) -> int:
    """The signal behind a KeyboardInterrupt (SIGINT unless it says otherwise)."""
    return int(getattr(exc, "signum", signal.SIGINT))


def exit_code(signum: int) -> tuple:
    """(signal name, 128 + signum)."""
    return signal.Signals(signum).name, 128 + int(signum)
