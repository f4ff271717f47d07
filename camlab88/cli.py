"""The one console script: ``camlab88 <subcommand> ...``.

Each area registers its own actions from ``camlab88.commands.<area>`` (a package whose
``ACTIONS`` tuple names one module per action, see camlab88.areas) so that the areas stay
independent; a command module only parses arguments and wires a program to a device through
the harness (emulator.harness), and imports heavy packages inside its handler so ``--help``
stays fast.
"""

from __future__ import annotations

import argparse
import errno
import importlib
import sys
from collections.abc import Sequence
from typing import NoReturn

from camlab88 import __version__
from camlab88.areas import register_area, register_command

# Order is the order shown in --help.
COMMAND_MODULES: tuple[str, ...] = (
    "demo",
    "sigma",
    "rainbow",
    "tablet",
    "link",
    "kas",
    "snooker",
    "ca",
    "replay",
    "figures",
    "warmup",
)


class _Parser(argparse.ArgumentParser):
    """argparse, with every parse error in one line — the message, "did you mean" for a
    misspelt subcommand, action or option, and where the usage is (``--help``) — instead
    of the usage block; and an option no command has named as unknown, even where argparse
    would first complain that a required one is missing (``--input`` for ``--in``)."""

    # the last parser that read the line (a subcommand's, once it is reached): its options
    # are the ones an unknown option is compared with, and its --help the one to see
    reading: _Parser | None = None

    def parse_known_args(self, args: Sequence[str] | None = None,
                         namespace: argparse.Namespace | None = None
                         ) -> tuple[argparse.Namespace, list[str]]:
        _Parser.reading = self
        self.words = list(sys.argv[1:] if args is None else args)
        return super().parse_known_args(args, namespace)

    def error(self, message: str) -> NoReturn:
        leaf = _Parser.reading or self
        unknown = leaf.unknown_options()
        if unknown and (message.startswith(("the following arguments are required",
                                            "unrecognized arguments"))):
            message = f"unknown option {unknown[0]}" + leaf.option_suggestion(unknown[0])
        elif "invalid choice:" in message:
            message += _suggestion(message)
        self.exit(2, f"{leaf.prog}: {message} (see {leaf.prog} --help)\n")

    def known_options(self) -> set[str]:
        """Every option string this parser's help names (its groups' too)."""
        import re

        return set(re.findall(r"(?<![\w-])(--?[A-Za-z][\w-]*)", self.format_help()))

    def unknown_options(self) -> list[str]:
        """The long options on the line that this parser does not take, not even as a
        unique abbreviation."""
        words = getattr(self, "words", [])
        words = words[:words.index("--")] if "--" in words else words
        known = None
        out = []
        for word in words:
            if not word.startswith("--") or word == "--":
                continue
            known = self.known_options() if known is None else known
            name = word.split("=", 1)[0]
            if name not in known and sum(k.startswith(name) for k in known) != 1:
                out.append(name)
        return out

    def option_suggestion(self, name: str) -> str:
        from camlab88.base.suggest import did_you_mean

        longs = sorted(k for k in self.known_options() if k.startswith("--"))
        stems = [k for k in longs if name.startswith(k)]  # --input for --in: the stem first
        return did_you_mean(name, stems[-1:] or longs)


def _suggestion(message: str) -> str:
    import re

    m = re.search(r"invalid choice: '([^']*)' \(choose from (.*)\)", message)
    if m is None:
        return ""
    choices = re.findall(r"'([^']*)'", m[2]) or [c.strip() for c in m[2].split(",")]
    from camlab88.base.suggest import did_you_mean

    return did_you_mean(m[1], choices)


def build_parser(words: Sequence[str] = ()) -> argparse.ArgumentParser:
    """The whole command line, or — when `words` starts with an area's name — only that
    area (the others' modules are not imported: ``ca run`` need not load snooker's)."""
    _Parser.reading = None
    parser = _Parser(
        prog="camlab88",
        description="Working models of the Sigma T5684/T5688 terminals and the Cambridge "
        "Rainbow workstation, and the 1987 animation programs that ran on them.",
    )
    parser.add_argument("--version", action="version", version=f"camlab88 {__version__}")
    parser.add_argument("--budget", metavar="SIZE",
                        help="the memory budget every reader and renderer checks an input "
                        "against before the work (1500M, 4G; default 1G, or the environment's "
                        "CAMLAB88_BUDGET): an input that would need more is refused in one "
                        "line (docs/reliability.md)")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    sub.words = tuple(words)  # an area builds only the action the line names (areas.py)
    for module in _command_modules(words):
        if hasattr(module, "ACTIONS"):
            register_area(sub, module.__name__, module.ACTIONS)
        else:
            register_command(sub, module.__name__, getattr(module, "NAME", None))
    parser.set_defaults(handler=lambda args: _bare(parser))
    return parser


def command_parser(parser: argparse.ArgumentParser,
                   words: Sequence[str]) -> argparse.ArgumentParser:
    """The parser of the command ``words`` name (``["ca", "run", ...]``: ``ca run``'s); as
    far as they name one (an area's, or the whole line's)."""
    for word in words:
        choices = next((a.choices for a in parser._actions
                        if isinstance(a, argparse._SubParsersAction)), {})
        if word not in choices:
            break
        parser = choices[word]
    return parser


def run_only_flags(parser: argparse.ArgumentParser) -> dict[str, int]:
    """The options declared run-only (``action.run_only``: how a run is shown or recorded,
    never what the program does) and the outputs (``.replay = SCRATCH``: where it writes,
    which the program rewrites as it runs), each with the number of values it takes (0 or
    1): what a save state's identity leaves out (emulator.harness.program_state)."""
    from camlab88.replay_policy import SCRATCH

    return {flag: 0 if action.nargs == 0 else 1 for action in parser._actions
            if getattr(action, "run_only", False) or getattr(action, "replay", None) == SCRATCH
            for flag in action.option_strings}


def _bare(parser: argparse.ArgumentParser) -> int:
    """Bare ``camlab88``: the help, not an error."""
    parser.print_help()
    return 0


def _command_modules(words: Sequence[str] = ()) -> list:
    names = COMMAND_MODULES
    if words and words[0] in COMMAND_MODULES:
        names = (words[0],)
    return [importlib.import_module(f"camlab88.commands.{name}") for name in names]


def normalise_argv(argv: Sequence[str]) -> list[str]:
    """Let an area rewrite its own command line first (e.g. ``camlab88 snooker SESSION``
    means ``camlab88 snooker play SESSION``); an area only ever rewrites a line that
    starts with its own name."""
    out = list(argv)
    for module in _command_modules(out):
        hook = getattr(module, "normalise_argv", None)
        if hook is not None:
            out = hook(out)
    return out


# Exit status, one rule for every command (docs/exit_status.md): 0 the work was done; 1 it
# started and failed (a check found differences, a finding, a connection lost, ...); 2 it
# could not start on what it was given (arguments, a missing or malformed input file, an
# output that cannot be written, a port or device that cannot be opened).
OK, FAILED, USAGE = 0, 1, 2


class Terminated(KeyboardInterrupt):
    """SIGTERM, delivered the way Ctrl-C is, so every program's clean-up (a ``--record``
    file finished and written, temporaries removed) runs for both."""


class HungUp(Terminated):
    """SIGHUP (the terminal or the ssh session closed): the same clean-up as SIGTERM."""


def _terminate(signum: int, frame: object) -> None:
    import signal

    raise HungUp if signum == getattr(signal, "SIGHUP", None) else Terminated


def _catch_sigterm() -> dict[int, object]:
    """Install the SIGTERM and SIGHUP handlers (main thread only); returns the handlers
    they replaced."""
    import signal
    import threading

    if threading.current_thread() is not threading.main_thread():
        return {}
    sigs = [signal.SIGTERM] + ([signal.SIGHUP] if hasattr(signal, "SIGHUP") else [])
    return {sig: signal.signal(sig, _terminate) for sig in sigs}


def main(argv: Sequence[str] | None = None) -> int:
    """Run one command; called without `argv` (as the program itself) the process then
    ends at once (see `_exit_now`)."""
    status = _main(argv)
    if argv is None:
        _exit_now(status)
    return status


def _exit_now(status: int) -> None:
    """End the process without tearing down the interpreter: atexit handlers run and the
    output is flushed, but the modules are not destroyed one by one — after numba is
    loaded that teardown alone costs 0.1-0.3 s of CPU, as much as a short command's work.
    Only when no other non-daemon thread is still running (normal exit would wait)."""
    import atexit
    import os
    import threading

    main_thread = threading.main_thread()
    waiting = [t for t in threading.enumerate()
               if t is not main_thread and not t.daemon and t.is_alive()]
    if threading.current_thread() is not main_thread or waiting:
        return
    atexit._run_exitfuncs()
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (OSError, ValueError):  # a closed pipe or stream: nothing more to say
            pass
    os._exit(status)


def _take_budget(words: list[str]) -> list[str]:
    """``--budget SIZE`` before the command sets ``CAMLAB88_BUDGET`` for this process and
    its children (so an area's own parser never sees it, and a Dask worker or a replayed
    program checks against the same budget)."""
    import os

    from camlab88.base import budget

    while words and (words[0] == "--budget" or words[0].startswith("--budget=")):
        if words[0] == "--budget":
            if len(words) < 2:
                raise SystemExit("camlab88: --budget needs a SIZE (1500M, 4G)")
            value, words = words[1], words[2:]
        else:
            value, words = words[0].partition("=")[2], words[1:]
        try:
            budget.parse_size(value)
        except ValueError as exc:
            raise SystemExit(f"camlab88: --budget: {exc}") from None
        os.environ[budget.ENV] = value
    return words


def _main(argv: Sequence[str] | None) -> int:
    words = normalise_argv(_take_budget(list(sys.argv[1:] if argv is None else argv)))
    args = (parser := build_parser(words)).parse_args(words)
    args._argv = words  # what a --record recording stores and a replay re-runs
    args._run_only = run_only_flags(command_parser(parser, words))
    previous = _catch_sigterm()
    try:
        result = args.handler(args)
    except HungUp:
        return 129  # 128 + SIGHUP
    except Terminated:
        return 143  # 128 + SIGTERM, as the shell reports a process it ended
    except KeyboardInterrupt:
        return 130
    except BrokenPipeError:
        return OK
    except MemoryError:  # a cost no budget check foresaw: still one line, no traceback
        command = _command(words)
        print(f"{command}: out of memory; the input needs more than this machine has "
              "(docs/reliability.md, \"Budget\")", file=sys.stderr)
        return FAILED
    except OSError as exc:
        return _write_fault(words, exc)
    except Exception as exc:
        return _refused_or_raise(words, args, exc)
    finally:
        if previous:
            import signal

            for sig, handler in previous.items():
                signal.signal(sig, handler)
    return int(result or 0)


def _refused_or_raise(words: list[str], args: argparse.Namespace, exc: Exception) -> int:
    """A command's exception that has a one-line answer: over the budget (status 2), a
    --save-state that could not save (1), a program failing on a --load-state (2); any
    other is a bug and propagates."""
    from camlab88.base.budget import OverBudget

    if isinstance(exc, OverBudget):  # refused before the work: one line, status 2
        print(f"{_command(words)}: {exc}", file=sys.stderr)
        return USAGE

    from camlab88.emulator.harness.program_state import StateNotSaved

    if isinstance(exc, StateNotSaved):  # --save-state could not save: said in one line
        print(exc, file=sys.stderr)
        return 1
    if getattr(args, "load_state", None) is None:
        raise exc
    return _state_fault(words, args.load_state, exc)


def _command(words: list[str]) -> str:
    """``camlab88 AREA ACTION`` as the line named it (``camlab88 replay``, not ``camlab88
    replay rec.session``: an action is a word, never a file name)."""
    named = [w for w in words[:2] if not w.startswith("-")]
    if len(named) == 2 and not named[1].replace("-", "").isalnum():
        named = named[:1]
    return " ".join(["camlab88", *named])


# what a full disk, a read-only mount or a directory in the way does to a writer
_WRITE_FAULTS = {errno.ENOSPC, errno.EDQUOT, errno.EROFS, errno.EISDIR, errno.ENOTDIR,
                 errno.EACCES, errno.EPERM, errno.EFBIG, errno.EIO, errno.ENXIO}


def _write_fault(words: list[str], exc: OSError) -> int:
    """A write that failed, as one line naming the user's file (the atomic writers leave
    the old file as it was and name the user's path, never their temporary file)."""
    if exc.filename is None or exc.errno not in _WRITE_FAULTS:
        raise exc
    command = _command(words)
    print(f"{command}: {exc.filename}: {exc.strerror}", file=sys.stderr)
    return 1


def _state_fault(words: list[str], state: object, exc: Exception) -> int:
    """A run continued from ``--load-state FILE`` failed: a state passes its checks when it
    names this program, version and inputs and its tree fits the program's objects, but its
    values are the program's own, unchecked — a damaged or hand-edited file can hold ones
    the program never makes. One line naming the file, status 2 (an input it was given)."""
    command = _command(words)
    print(f"{command}: {state}: the program failed on this state ({type(exc).__name__}: "
          f"{exc}); is the file damaged or edited?", file=sys.stderr)
    return 2


def _one_blas_thread() -> None:
    """numpy's OpenBLAS starts a thread per core at import, and they spin: 30-60 ms of CPU
    a process here, a third of numpy's import, and BLAS does little for us (our products
    are rows of 3-vectors by 3 x 3 matrices). Set before numpy is imported; a user's own
    setting wins; child processes inherit it."""
    import os

    if "numpy" not in sys.modules:
        os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")


def _user_kernel_cache() -> None:
    """numba caches compiled kernels beside their sources by default, and for an installed
    camlab88 that is inside site-packages, where pip never removes them. The command caches
    them per user instead (``$XDG_CACHE_HOME/camlab88/numba``, else ``~/.cache/...``), through
    numba's documented ``NUMBA_CACHE_DIR``; a user's own setting wins; children inherit it."""
    import os

    if "numba" in sys.modules or "NUMBA_CACHE_DIR" in os.environ:
        return
    if os.name == "nt":
        home = os.environ.get("LOCALAPPDATA") or os.path.expanduser("~")
    else:
        home = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    os.environ["NUMBA_CACHE_DIR"] = os.path.join(home, "camlab88", "numba")


def entry(argv: Sequence[str] | None = None) -> int:
    """The console script and ``python -m camlab88``: ``main``, with a command's one-line
    refusal (``SystemExit("camlab88 X: why")``, which Python would end with status 1)
    printed and ended with status 2, a usage or input error like every other."""
    _one_blas_thread()
    _user_kernel_cache()
    try:
        return main(argv)
    except SystemExit as exc:
        if not isinstance(exc.code, str):
            raise
        print(exc.code, file=sys.stderr)
        return USAGE


if __name__ == "__main__":  # pragma: no cover
    sys.exit(entry())
