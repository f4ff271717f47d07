"""Quitting over unsaved work, the same in every program that asks (the KAS fronts, the
actor editor): with nothing unsaved the program ends at once; with unsaved work the message
line asks first — y saves and quits, n quits without saving, Esc stays — and a second close
while asked quits without saving."""

from __future__ import annotations

QUIT_QUESTION = "unsaved work: y saves and quits, n quits without saving, Esc stays"


class AsksBeforeQuitting:
    """Mixin: ``request_quit`` / ``may_close`` / ``answer_quit``. The program provides
    ``unsaved``, ``save_work``, ``ask_quit`` (show the question), ``stay`` (Esc: clear it)
    and ``end`` (stop), and sets ``asking`` and ``discarded`` False at the start."""

    asking: bool     # the quit question is on the message line
    discarded: bool  # the user chose to drop unsaved work

    def unsaved(self) -> bool:
        raise NotImplementedError

    def save_work(self) -> bool:
        raise NotImplementedError

    def ask_quit(self) -> None:
        raise NotImplementedError

    def stay(self) -> None:
        raise NotImplementedError

    def end(self) -> None:
        raise NotImplementedError

    def may_close(self) -> bool:
        """The window's close button: True to close now (asks first over unsaved work)."""
        return self.request_quit(closing=True)

    def request_quit(self, closing: bool = False) -> bool:
        """Esc or close: quit now if nothing is unsaved, else ask."""
        if self.asking and closing:
            self.discarded = True
        elif self.unsaved():
            self.asking = True
            self.ask_quit()
            return False
        self.asking = False
        self.end()
        return True

    def answer_quit(self, key: str) -> None:
        """A key pressed while the question is asked."""
        k = key.lower()
        if k == "y":
            self.asking = False
            if self.save_work():
                self.end()
        elif k == "n":
            self.asking = False
            self.discarded = True
            self.end()
        elif k == "escape":
            self.asking = False
            self.stay()
        else:
            self.ask_quit()
