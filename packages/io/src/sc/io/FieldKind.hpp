#pragma once
// What a field's components mean, so that ParaView shows vectors as arrows and tensors as tensors.
// Input layouts per space dimension d (values are interleaved per vertex / cell):
//   Scalar           1 value
//   Vector           d values (x, y[, z])
//   Tensor           d*d values, row-major (xx, xy, yx, yy) or (xx, xy, xz, yx, ..., zz)
//   SymmetricTensor  2D: 3 values (xx, yy, xy); 3D: 6 values in Voigt order (xx, yy, zz, yz, xz,
//   xy)
// The writer stores vectors with 3 and tensors with 9 components (zero-padded in 2D, symmetric
// ones expanded), the layouts ParaView's XDMF reader understands unambiguously.

#include <string>

namespace sc::io {

enum class FieldKind { Scalar, Vector, Tensor, SymmetricTensor };

/// Components per entity in the caller's layout (see above) for space dimension \p dim.
int inputComponents(FieldKind kind, int dim);

/// Components stored in HDF5: 1, 3, 9, 9.
int storedComponents(FieldKind kind);

/// XDMF AttributeType: "Scalar", "Vector", "Tensor".
std::string xdmfAttributeType(FieldKind kind);

std::string fieldKindName(FieldKind kind);

}  // namespace sc::io
