"""The program harness: one run loop for every interactive program and the demo.

A command builds a *target* — an object wiring one program to one emulated device (see
:class:`Target`: ``title``, ``size``, ``fps``, ``keys``, ``handle_events``, ``tick``,
``frame``, ``time``; optionally ``may_close``, ``wire``, ``put_wire``, ``finish``) — and calls
``run(target, options)``.  The harness then:

* opens a window or runs headless (``options.headless``, decided once by
  :func:`choose_headless`: no display -> headless if the command can do useful work headless,
  saying so; otherwise a one-line refusal; never an invisible window), and prints the
  target's key hint when a window opens;
* ticks the target; each tick it polls the window, passes the host events through the
  plugins (``handle_events``), stops on Quit (if ``target.may_close()``), hands the events to
  the target, ticks it, shows a frame whenever ``target.time()`` has advanced by ``1/fps``
  (``on_frame``), then ``post_tick``;
* paces the wall clock to ``target.time()`` in a window (``options.paced``), otherwise runs
  flat out; a ``--screenshot`` run is never paced;
* stops when ``tick()`` returns False, the window closes, ``options.stop_after`` frames have
  been shown, or a plugin calls ``harness.stop()``;
* standard plugins: ``--frames DIR`` (every frame shown as ``DIR/frame_NNNNN.png``),
  ``--screenshot PNG`` (the screen at the end), ``--record FILE`` (a session recording,
  protocols.session), and under ``camlab88 replay`` the recorded input and hash checking.
* the emulator controls, first of the plugins: F1 help, F5 pause, F6 one frame, F7/F8
  speed, F11 inspector, F12 screenshot, Esc quit; ``--speed X`` (emulator.harness.pace),
  ``--video FILE``, ``--inspect``, ``--inspect-out DIR`` (``RunOptions.controls``).

All PNGs go through the one writer, :func:`camlab88.base.png.write_png`.  See docs/harness.md.
"""

from camlab88.emulator.harness.display import DisplayRefused, choose_headless, display_available
from camlab88.emulator.harness.loop import Harness, Plugin, RunOptions, Target, run

__all__ = ["DisplayRefused", "Harness", "Plugin", "RunOptions", "Target", "choose_headless",
           "display_available", "run"]
