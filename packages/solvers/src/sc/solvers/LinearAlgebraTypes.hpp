#pragma once
// The Tpetra types of the solvers' public API, forward-declared so that headers stay cheap to
// include (docs/theory.md §"Parallel model": Scalar double, LO int, GO long long, Serial node =
// Tpetra's defaults).

#include <Tpetra_CrsMatrix_fwd.hpp>
#include <Tpetra_Map_fwd.hpp>
#include <Tpetra_MultiVector_fwd.hpp>
#include <Tpetra_Vector_fwd.hpp>

namespace sc::solvers {

using CrsMatrix = Tpetra::CrsMatrix<>;
using MultiVector = Tpetra::MultiVector<>;
using Vector = Tpetra::Vector<>;
using Map = Tpetra::Map<>;

}  // namespace sc::solvers
