"""``camlab88 ca actors FILE``: the 3-D picture editor for a rule set's cell types (thesis
section 8.1) on the emulated Rainbow."""

from __future__ import annotations

import argparse
import sys

from camlab88.base.plainstate import Bool, Opt, Record, Str
from camlab88.rainbow_tablet import add_tablet_option
from camlab88.replay_policy import KEEP
from camlab88.runopts import add_run_options
from camlab88.scriptopts import HEADLESS_NEEDS_EVENTS, add_events_option

COMMAND = "camlab88 ca actors"
KEYS = """\
left: add/drag a point, set a slider; right: delete a point; middle: menu; s save; Tab next \
cell type; q, Esc or close the window to quit"""

DESCRIPTION = f"""\
Edit a rule set's actors file on the emulated Rainbow: pick a cell type, draw its lathe \
profile, watch the solid turn, set colour and material, save (docs/ca_actors.md). \
{HEADLESS_NEEDS_EVENTS} A --screenshot run never saves."""


HELP = "the 3-D picture editor for cell types (section 8.1)"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("file", metavar="FILE", help="the actors file (created by the first save)")
    p.add_argument("--rules",
                   help="rule file or library name whose cell types are edited (default: "
                        "the one FILE names, else life)").replay = KEEP
    add_events_option(p)
    add_tablet_option(p, what="draw with", where=": its surface maps onto the profile pad")
    add_run_options(p)


def run(args: argparse.Namespace) -> int:
    from camlab88.apps.ca.rules import RuleError
    from camlab88.base.atomicfile import probe
    from camlab88.protocols.rainbow.script import ScriptError
    from camlab88.rainbow_tablet import open_tablet
    from camlab88.runopts import fail
    from camlab88.scriptopts import events_player, scripted_run_options

    try:
        rules_name = args.rules or _rules_of(args.file)
        types = _cell_types(rules_name)
        player = events_player(args.events)
        opts = scripted_run_options(args, COMMAND, player)
        if opts.screenshot is None:  # a save must be possible before the editing starts
            probe(args.file)
    except (OSError, RuleError, ScriptError, ValueError) as exc:
        return fail(COMMAND, exc)
    tablet = open_tablet(COMMAND, args.tablet, opts)
    try:
        editor = _run(args.file, types, rules_name, player, opts, tablet)
    finally:
        if tablet is not None:
            tablet.close()
    return _report(editor)


def _rules_of(path: str) -> str:
    """The rule set an existing actors file names; life for a new or unreadable one (the
    editor reports why it did not load)."""
    from camlab88.apps.actors.model import ActorFileError, read_actors

    try:
        return read_actors(path).rules
    except (ActorFileError, OSError):
        return "life"


def _cell_types(rules: str) -> list:
    """The rule set's states as the editor's cell types: number, name, colour."""
    from camlab88.apps.actors.editor.cell_types import CellType
    from camlab88.apps.actors.model import MAX_STATE
    from camlab88.apps.ca import library
    from camlab88.apps.ca.render import default_colour
    from camlab88.apps.ca.rules import parse_rules

    path = library.rules_path(rules)
    with open(path, encoding="utf-8") as f:
        rs = parse_rules(f.read(), path)
    types = []
    for t in range(1, min(max(1, rs.max_form), MAX_STATE) + 1):
        form = rs.forms.get(t)
        colour = form.colour if form is not None and form.colour else default_colour(t)
        types.append(CellType(t, f"form {t}", tuple(colour)))
    return types


class _Session:
    """The editor, made at the first tick (so a --load-state can give it the FILE its
    session started from first: a save rewrites FILE), and what the target calls."""

    def __init__(self, machine, path: str, types: list, rules: str, may_save: bool) -> None:
        self.machine, self.made_of = machine, (path, types, rules, may_save)
        self.made = None
        self.given: list[dict] = []
        self.holding = False  # a load runs the session again: saves write nothing
        self.target = None  # the RainbowTarget it steps (its tablet may change)

    def editor(self):
        if self.made is None:
            from camlab88.apps.actors.editor.program import ActorEditor

            path, types, rules, may_save = self.made_of
            self.made = ActorEditor(self.machine.client, path, types, rules, may_save=may_save,
                                    start=self.given[0] if self.given else None)
        return self.made

    def step(self) -> bool:
        ed = self.editor()
        ed.writes = not self.holding
        tablet = self.target.tablet
        if tablet is not None and not tablet.gone:
            _poll_tablet(tablet, self.machine, ed)
        ed.frame()
        return not ed.finished

    def rebuilding(self, on: bool) -> None:
        self.holding = on
        if self.made is not None:
            self.made.writes = not on


def _run(path: str, types: list, rules: str, player, opts, tablet):
    from camlab88.emulator.harness import run
    from camlab88.emulator.harness.input_log import StartState
    from camlab88.emulator.harness.rainbow import RainbowTarget
    from camlab88.emulator.machine import RainbowMachine
    from camlab88.runopts import unattended

    machine = RainbowMachine(record=opts.record is not None)
    session = _Session(machine, path, types, rules, opts.screenshot is None)
    target = RainbowTarget(machine, session.step, "camlab88 ca actors", KEYS, player,
                           unattended(opts))
    session.target = target
    target.asks_before_closing(lambda: session.editor().may_close())
    target.tablet = tablet
    target.keep_input(StartState(START, lambda: session.editor().start, session.given.append,
                                 (path,)), session.rebuilding)
    run(target, opts)
    return session.editor()


# what FILE held when the session began, in its save state (the editor's ``start``)
START = Record(exists=Bool(), text=Opt(Str(4 << 20)), error=Opt(Str(4096)))


def _poll_tablet(tablet, machine, editor) -> None:
    """New tablet reports to the device's tablet input, the pen scaled to the tablet's
    range; a lost tablet is reported once and dropped."""
    from camlab88.rainbow_tablet import feed_tablet

    model = getattr(tablet.source, "model", None)
    if model is not None:
        editor.pen.extent = (max(1, model.max_x), max(1, model.max_y))
        editor.pen.flip = getattr(model, "origin", "upper-left") == "lower-left"
    feed_tablet(COMMAND, tablet, machine)


def _report(editor) -> int:
    """One line on stderr for what the session left: a file that did not load and was not
    replaced (exit 1), or work not saved."""
    if editor.load_error is not None:
        print(f"{COMMAND}: {editor.load_error}", file=sys.stderr)
        return 1
    if editor.unsaved():
        print(f"{COMMAND}: {editor.path}: the last changes were not saved", file=sys.stderr)
    return 0
