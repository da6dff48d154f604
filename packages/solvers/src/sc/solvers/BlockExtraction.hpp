#pragma once
// Blocks of the monolithic mixed system for the block preconditioner of docs/theory.md §"Linear
// solvers" (IterativeSolver): the rows of one field, the block of two fields, the exact inverse of
// the element-block-diagonal displacement mass. Tpetra stays in BlockExtraction.cpp.

#include <vector>

#include <Teuchos_RCP.hpp>

#include <sc/solvers/LinearAlgebraTypes.hpp>

namespace sc::solvers {

/// The owned rows of `map` whose global ids lie in [begin, end), as a map with the same global ids;
/// `localIndices` receives the local indices in `map` of those rows.
Teuchos::RCP<const Map> subMap(const Map& map, long long begin, long long end,
                               std::vector<int>& localIndices);

/// The block of K with rows `rowMap` (a subset of K's owned rows, same global ids) and columns in
/// [colBegin, colEnd), as a fill-complete matrix with domain `domainMap` and range `rowMap`.
Teuchos::RCP<CrsMatrix> extractBlock(const CrsMatrix& K, const Teuchos::RCP<const Map>& rowMap,
                                     long long colBegin, long long colEnd,
                                     const Teuchos::RCP<const Map>& domainMap);

/// Exact inverse of a block-diagonal SPD matrix whose blocks are owned by one rank each (the
/// displacement mass of discontinuous elements): rows with the same smallest column id form a
/// block.
Teuchos::RCP<CrsMatrix> blockInverse(const CrsMatrix& M);

}  // namespace sc::solvers
