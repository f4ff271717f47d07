"""base/raw_views.py: arrays handed between compiled kernels by address come back as the
same memory, with their shapes and element types, writable, for each dtype HashLife uses."""

from __future__ import annotations

import numpy as np
from camlab88.base import raw_views
from numba import njit

raw_views.arm()


@njit(cache=False)
def _through_addresses(a, b, c):
    return _round_trip(raw_views.address(a), raw_views.address(b), raw_views.address(c),
                       a.shape[0], a.shape[1], b.shape[0], c.shape[0], c.shape[1])


# As HashLife's kernels run: without reference counts, so it returns no array (an array
# handed back from such a kernel would be released twice by a caller that counts them).
@njit(_nrt=False, cache=False)
def _round_trip(pa, pb, pc, ra, ca, nb, rc, cc):
    a = raw_views.matrix_at(pa, ra, ca, np.int32(0))
    b = raw_views.vector_at(pb, nb, np.int64(0))
    c = raw_views.matrix_at(pc, rc, cc, np.uint64(0))
    a[ra - 1, ca - 1] += 1  # writes land in the caller's arrays
    b[nb - 1] = -b[0]
    c[1, 2] = c[rc - 1, cc - 1] + np.uint64(1)
    return (a[2, 3] + b[5] + np.int64(c[0, 1]), a.strides[0], a.strides[1], b.strides[0],
            c.strides[0], c.strides[1])


def test_views_are_the_arrays_themselves() -> None:
    a = np.arange(4 * 8, dtype=np.int32).reshape(4, 8)
    b = np.arange(10, 20, dtype=np.int64)
    c = np.arange(6 * 5, dtype=np.uint64).reshape(6, 5)
    total, *strides = _through_addresses(a, b, c)
    assert total == a[2, 3] + b[5] + c[0, 1]
    assert strides == [*a.strides, *b.strides, *c.strides]
    assert a[3, 7] == 4 * 8 - 1 + 1 and b[9] == -10 and c[1, 2] == 6 * 5 - 1 + 1


def test_arming_is_idempotent_and_names_the_intrinsics() -> None:
    first = raw_views.address
    raw_views.arm()
    assert raw_views.address is first
    assert {"address", "matrix_at", "vector_at"} <= set(vars(raw_views))
