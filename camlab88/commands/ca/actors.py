"""``camlab88 ca actors FILE``: the 3-D picture editor for a rule set's cell types (thesis
section 8.1) on the emulated Rainbow."""

from __future__ import annotations

import argparse
import sys

COMMAND = "camlab88 ca actors"
KEYS = ("left: add/drag a point, set a slider; right: delete a point; middle: menu; s save; "
        "Tab next cell type; q, Esc or close the window to quit")


def register(actions: argparse._SubParsersAction) -> None:
    from camlab88.runopts import add_run_options

    p = actions.add_parser(
        "actors", help="the 3-D picture editor for cell types (section 8.1)",
        description="Edit a rule set's actors file on the emulated Rainbow: pick a cell type, "
        "draw its lathe profile, watch the solid turn, set colour and material, save "
        "(docs/ca_actors.md). Headless it needs --events (the run ends with the script) or "
        "--stop-after N. A --screenshot run never saves.")
    p.add_argument("file", metavar="FILE", help="the actors file (created by the first save)")
    p.add_argument("--rules",
                   help="rule file or library name whose cell types are edited (default: "
                   "the one FILE names, else life)")
    p.add_argument("--events", metavar="FILE",
                   help="scripted mouse/keyboard input (the Rainbow script format, "
                   "docs/harness.md)")
    p.add_argument("--tablet", metavar="SOURCE",
                   help="also draw with a real tablet (hid:VID:PID, serial:PORT?protocol=P, "
                   "or a pyserial URL?protocol=P): its surface maps onto the profile pad")
    add_run_options(p)
    p.set_defaults(handler=actors)


def actors(args: argparse.Namespace) -> int:
    from apps.ca.rules import RuleError
    from base.atomicfile import probe
    from camlab88.runopts import fail, run_options
    from protocols.rainbow.script import Player, ScriptError, load

    try:
        rules_name = args.rules or _rules_of(args.file)
        types = _cell_types(rules_name)
        player = Player(load(args.events)) if args.events else None
        useful = "playing the --events script" if player else (
            "for --stop-after frames" if args.stop_after else None)
        opts = run_options(args, COMMAND, useful, "give --headless with --events FILE",
                           getattr(args, "_argv", None))
        if opts.screenshot is None:  # a save must be possible before the editing starts
            probe(args.file)
    except (OSError, RuleError, ScriptError, ValueError) as exc:
        return fail(COMMAND, exc)
    if opts.headless and player is None and opts.stop_after is None:
        opts.stop_after = 100
    tablet = _open_tablet(args.tablet, opts.record is not None)
    if tablet is not None and tablet.live:  # a real stylus moves on the wall clock
        opts.live = True
    try:
        editor = _run(args.file, types, rules_name, player, opts, tablet)
    finally:
        if tablet is not None:
            tablet.close()
    return _report(editor)


def _rules_of(path: str) -> str:
    """The rule set an existing actors file names; life for a new or unreadable one (the
    editor reports why it did not load)."""
    from apps.actors.model import ActorFileError, read_actors

    try:
        return read_actors(path).rules
    except (ActorFileError, OSError):
        return "life"


def _cell_types(rules: str) -> list:
    """The rule set's states as the editor's cell types: number, name, colour."""
    from apps.actors.editor.cell_types import CellType
    from apps.actors.model import MAX_STATE
    from apps.ca import library
    from apps.ca.render import default_colour
    from apps.ca.rules import parse_rules

    path = library.rules_path(rules)
    with open(path, encoding="utf-8") as f:
        rs = parse_rules(f.read(), path)
    types = []
    for t in range(1, min(max(1, rs.max_form), MAX_STATE) + 1):
        form = rs.forms.get(t)
        colour = form.colour if form is not None and form.colour else default_colour(t)
        types.append(CellType(t, f"form {t}", tuple(colour)))
    return types


def _run(path: str, types: list, rules: str, player, opts, tablet):
    from apps.actors.editor.program import ActorEditor
    from emulator.harness import run
    from emulator.harness.rainbow import RainbowTarget
    from emulator.rainbow.session import in_process

    session = in_process(record=opts.record is not None)
    editor = ActorEditor(session.client, path, types, rules,
                         may_save=opts.screenshot is None)

    def step() -> bool:
        if target.tablet is not None and not target.tablet.gone:
            _poll_tablet(target.tablet, session, editor)
        editor.frame()
        return not editor.finished

    end_with_script = opts.headless or opts.screenshot is not None
    target = RainbowTarget(session, step, "camlab88 ca actors", KEYS, player, end_with_script)
    target.may_close = editor.may_close
    target.tablet = tablet
    run(target, opts)
    return editor


def _open_tablet(text: str | None, record: bool):
    """The --tablet source (on a tape with --record; from the recording's tape in a replay,
    where the device is never opened)."""
    if not text:
        return None
    from emulator.tablet_input.taped import TapedTablet
    from protocols.tablets.sources import SourceError

    try:
        return TapedTablet.open(text, record)
    except (SourceError, OSError) as exc:
        raise SystemExit(f"{COMMAND}: --tablet {text}: {exc}") from None


def _poll_tablet(tablet, session, editor) -> None:
    """New tablet reports to the device's tablet input, the pen scaled to the tablet's
    range; a lost tablet is reported once and dropped."""
    from emulator.rainbow.host_input import tablet_event
    from protocols.tablets.sources import SourceLost

    model = getattr(tablet.source, "model", None)
    if model is not None:
        editor.pen.extent = (max(1, model.max_x), max(1, model.max_y))
        editor.pen.flip = getattr(model, "origin", "upper-left") == "lower-left"
    try:
        for ev in tablet.read(0.0):
            session.inject(tablet_event(ev))
    except (SourceLost, OSError) as exc:
        print(f"{COMMAND}: tablet lost ({exc}); carrying on without it", file=sys.stderr)
        tablet.close()


def _report(editor) -> int:
    """One line on stderr for what the session left: a file that did not load and was not
    replaced (exit 1), or work not saved."""
    if editor.load_error is not None:
        print(f"{COMMAND}: {editor.load_error}", file=sys.stderr)
        return 1
    if editor.unsaved():
        print(f"{COMMAND}: {editor.path}: the last changes were not saved", file=sys.stderr)
    return 0
