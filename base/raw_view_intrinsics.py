"""The numba intrinsics behind base/raw_views.py (imported only when a kernel using them is
compiled)."""

from __future__ import annotations

from typing import Any

from numba import types
from numba.core import cgutils
from numba.extending import intrinsic


@intrinsic
def address(typingctx: Any, array: types.Type) -> Any:
    """The address of a C-ordered array's data, as an int64."""
    if not isinstance(array, types.Array) or array.layout != "C":
        return None

    def codegen(context, builder, signature, args):
        data = context.make_array(signature.args[0])(context, builder, args[0]).data
        return builder.ptrtoint(data, cgutils.intp_t)

    return types.int64(array), codegen


def _array_at(context, builder, array_type, at, dims):
    """A numba array of ``array_type`` (C order) at address ``at``, owning nothing."""
    item = context.get_data_type(array_type.dtype)
    size = context.get_abi_sizeof(item)
    data = builder.inttoptr(at, item.as_pointer())
    strides, stride = [], context.get_constant(types.intp, size)
    for dim in reversed(dims[1:]):
        strides.insert(0, stride)
        stride = builder.mul(stride, dim)
    strides.insert(0, stride)
    array = context.make_array(array_type)(context, builder)
    context.populate_array(array, data=data, shape=cgutils.pack_array(builder, dims),
                           strides=cgutils.pack_array(builder, strides),
                           itemsize=context.get_constant(types.intp, size), meminfo=None)
    return array._getvalue()


@intrinsic
def matrix_at(typingctx: Any, at: types.Type, rows: types.Type, columns: types.Type,
         like: types.Type) -> Any:
    """The C-ordered ``rows`` x ``columns`` array of ``like``'s type at address ``at``."""
    if not all(isinstance(t, types.Integer) for t in (at, rows, columns, like)):
        return None
    array_type = types.Array(like, 2, "C")

    def codegen(context, builder, signature, args):
        dims = [context.cast(builder, args[i], signature.args[i], types.intp) for i in (1, 2)]
        return _array_at(context, builder, array_type, args[0], dims)

    return array_type(at, rows, columns, like), codegen


@intrinsic
def vector_at(typingctx: Any, at: types.Type, n: types.Type, like: types.Type) -> Any:
    """The array of ``n`` values of ``like``'s type at address ``at``."""
    if not all(isinstance(t, types.Integer) for t in (at, n, like)):
        return None
    array_type = types.Array(like, 1, "C")

    def codegen(context, builder, signature, args):
        dims = [context.cast(builder, args[1], signature.args[1], types.intp)]
        return _array_at(context, builder, array_type, args[0], dims)

    return array_type(at, n, like), codegen
