"""Arrays handed between compiled kernels by address, for kernels that call each other
very often (HashLife's recursion: apps/ca/hashlife/evolve.py).

numba passes each array argument of a compiled call as its struct's 7 to 9 fields, and a
call of the recursion took 9 arrays: 57 arguments, most of them pushed on the stack every
call (13 ns a call with 7 arrays against 2 with two addresses, measured).  So the kernel
Python calls writes its arrays' addresses and sizes into an int64 array and the kernels it
calls rebuild the arrays from them, as numba arrays owning nothing: they are valid only
while that first call runs, which keeps the real arrays alive.

``address(array)`` (int64) and ``matrix_at(address, rows, columns, like)`` (a C-ordered
``rows`` x ``columns`` array of ``like``'s type; ``vector_at(address, n, like)`` for one
dimension; not ``view``: numba refuses a call of that name unless it is an array's) are
numba intrinsics, usable only inside compiled kernels.  They are defined here by ``arm()``,
which base.kernel_set calls whenever it compiles (numba's typing looks the names up in this
module's namespace, so they must be there by then): a process running ahead-of-time
extensions never imports numba for them.
"""

from __future__ import annotations


def arm() -> None:
    """Define ``address``, ``matrix_at`` and ``vector_at`` (imports numba).  Idempotent."""
    if "address" in globals():
        return
    from camlab88.base import raw_view_intrinsics as impl

    globals().update(address=impl.address, matrix_at=impl.matrix_at,
                     vector_at=impl.vector_at)
