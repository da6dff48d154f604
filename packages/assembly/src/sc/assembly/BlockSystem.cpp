#include "sc/assembly/BlockSystem.hpp"

#include <algorithm>
#include <array>
#include <numeric>
#include <vector>

#include <Teuchos_Array.hpp>
#include <Thyra_DefaultBlockedLinearOp.hpp>
#include <Thyra_DefaultProductMultiVector.hpp>
#include <Thyra_DefaultProductVectorSpace.hpp>
#include <Thyra_TpetraLinearOp.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Thyra_TpetraVectorSpace.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>

#include <sc/core/Collective.hpp>
#include <sc/core/Error.hpp>
#include <sc/disc/MixedElasticitySpace.hpp>

namespace sc::assembly {
namespace {

using LO = Map::local_ordinal_type;
using GO = Map::global_ordinal_type;
using Node = Map::node_type;
using Extract = Thyra::TpetraOperatorVectorExtraction<double, LO, GO, Node>;

// σ couples to every field; u and θ only to σ (docs/theory.md §"Mixed formulation").
bool structurallyNonzero(int row, int col) { return row == 0 || col == 0; }

}  // namespace

long long FieldLayout::size(int field) const
{
  return field == 0 ? stressDofs : field == 1 ? displacementDofs : rotationDofs;
}

struct BlockSystem::Impl {
  Teuchos::RCP<const CrsMatrix> monolithic;
  std::array<Teuchos::RCP<const Map>, numFields> maps;
  /// Local index in the monolithic owned map of each local DOF of a field map.
  std::array<std::vector<LO>, numFields> monolithicLocal;
  std::array<std::array<Teuchos::RCP<const CrsMatrix>, numFields>, numFields> blocks;
  std::array<Teuchos::RCP<const Thyra::VectorSpaceBase<double>>, numFields> spaces;
  Teuchos::RCP<const Thyra::DefaultProductVectorSpace<double>> product;
  Teuchos::RCP<const Thyra::LinearOpBase<double>> op;
};

BlockSystem::BlockSystem(const MixedElasticityAssembler& assembler, double twoMu)
    : BlockSystem(assembler.matrix(),
                  FieldLayout{assembler.space().numStressDofs(),
                              assembler.space().numDisplacementDofs(),
                              assembler.space().numRotationDofs()},
                  twoMu)
{
}

BlockSystem::BlockSystem(Teuchos::RCP<const CrsMatrix> monolithic, const FieldLayout& layout,
                         double twoMu)
    : layout_(layout), twoMu_(twoMu), impl_(std::make_unique<Impl>())
{
  SC_THROW_IF(monolithic.is_null() || !monolithic->isFillComplete(), core::InternalError,
              "BlockSystem needs an assembled (fill-complete) monolithic matrix");
  SC_THROW_IF(
      static_cast<long long>(monolithic->getGlobalNumRows()) != layout.total(), core::InternalError,
      "BlockSystem: the matrix has "
          << monolithic->getGlobalNumRows() << " rows but the field layout " << layout.stressDofs
          << " + " << layout.displacementDofs << " + " << layout.rotationDofs << " DOFs");
  SC_THROW_IF(!(twoMu > 0.0), core::InternalError,
              "BlockSystem: scaling 2μ = " << twoMu << " must be > 0");
  impl_->monolithic = std::move(monolithic);
  build(*impl_->monolithic);
}

BlockSystem::~BlockSystem() = default;

void BlockSystem::build(const CrsMatrix& M)
{
  auto& I = *impl_;
  const Map& rowMap = *M.getRowMap();
  const Map& colMap = *M.getColMap();
  const auto comm = rowMap.getComm();
  // Field maps are cut from the row map; vectors of the range/domain map must split the same way.
  SC_THROW_IF(
      !M.getRangeMap()->isSameAs(rowMap) || !M.getDomainMap()->isSameAs(rowMap),
      core::InternalError,
      "BlockSystem needs a matrix whose row, range and domain maps are the same (owned) map");
  const LO nRows = static_cast<LO>(rowMap.getNodeNumElements());
  const LO nCols = static_cast<LO>(colMap.getNodeNumElements());

  // Field maps: owned rows split by field, global ids shifted to start at 0 in each field.
  std::array<std::vector<GO>, numFields> fieldGids;
  for (LO r = 0; r < nRows; ++r) {
    const GO g = rowMap.getGlobalElement(r);
    const int f = layout_.fieldOf(g);
    fieldGids[f].push_back(g - layout_.begin(f));
    I.monolithicLocal[f].push_back(r);
  }
  for (int f = 0; f < numFields; ++f)
    I.maps[f] = Teuchos::rcp(new Map(static_cast<Tpetra::global_size_t>(layout_.size(f)),
                                     Teuchos::ArrayView<const GO>(fieldGids[f]), 0, comm));

  std::vector<int> colField(nCols);
  for (LO c = 0; c < nCols; ++c)
    colField[c] = layout_.fieldOf(colMap.getGlobalElement(c));

  // The zero blocks are left out: refuse a matrix with non-zero values there (on all ranks, so
  // that none is left waiting in a collective call).
  typename CrsMatrix::local_inds_host_view_type cols;
  typename CrsMatrix::values_host_view_type vals;
  long long dropped = 0;
  for (int bi = 1; bi < numFields; ++bi)
    for (LO r : I.monolithicLocal[bi]) {
      M.getLocalRowView(r, cols, vals);
      for (std::size_t k = 0; k < cols.extent(0); ++k)
        if (!structurallyNonzero(bi, colField[cols(k)]) && vals(k) != 0.0) ++dropped;
    }
  const long long droppedAll = core::sumOverRanks(*comm, dropped);
  SC_THROW_IF(droppedAll > 0, core::InternalError,
              "BlockSystem: the matrix has "
                  << droppedAll
                  << " non-zero entries in the uu, uθ, θu "
                     "or θθ blocks, which the mixed elasticity system has as zero blocks "
                     "(docs/theory.md §\"Mixed formulation\")");

  // Each non-zero block as local CSR arrays on a column map made of the columns of M it uses
  // (in M's column-map order, so sorted rows stay sorted).
  std::vector<LO> blockCol(nCols);
  for (int bi = 0; bi < numFields; ++bi)
    for (int bj = 0; bj < numFields; ++bj) {
      if (!structurallyNonzero(bi, bj)) continue;
      const auto& rows = I.monolithicLocal[bi];
      std::fill(blockCol.begin(), blockCol.end(), LO(-1));
      std::size_t nnz = 0;
      for (LO r : rows) {
        M.getLocalRowView(r, cols, vals);
        for (std::size_t k = 0; k < cols.extent(0); ++k)
          if (colField[cols(k)] == bj) {
            blockCol[cols(k)] = 0;
            ++nnz;
          }
      }
      std::vector<GO> colGids;
      for (LO c = 0; c < nCols; ++c)
        if (blockCol[c] >= 0) {
          blockCol[c] = static_cast<LO>(colGids.size());
          colGids.push_back(colMap.getGlobalElement(c) - layout_.begin(bj));
        }
      auto blockColMap =
          Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                               Teuchos::ArrayView<const GO>(colGids), 0, comm));
      const double scale = bi == 0 && bj == 0 ? twoMu_ : 1.0;
      Teuchos::ArrayRCP<std::size_t> ptr(rows.size() + 1);
      Teuchos::ArrayRCP<LO> ind(nnz);
      Teuchos::ArrayRCP<double> val(nnz);
      std::size_t pos = 0;
      ptr[0] = 0;
      std::vector<std::pair<LO, double>> row;
      for (std::size_t lr = 0; lr < rows.size(); ++lr) {
        M.getLocalRowView(rows[lr], cols, vals);
        row.clear();
        for (std::size_t k = 0; k < cols.extent(0); ++k)
          if (colField[cols(k)] == bj) row.emplace_back(blockCol[cols(k)], scale * vals(k));
        // expertStaticFillComplete takes the rows as sorted; M's are, but do not rely on it.
        std::sort(row.begin(), row.end(),
                  [](const auto& a, const auto& b) { return a.first < b.first; });
        for (const auto& [c, v] : row) {
          ind[pos] = c;
          val[pos] = v;
          ++pos;
        }
        ptr[lr + 1] = pos;
      }
      auto B = Teuchos::rcp(new CrsMatrix(I.maps[bi], blockColMap, ptr, ind, val));
      B->expertStaticFillComplete(I.maps[bj], I.maps[bi]);
      I.blocks[bi][bj] = B;
    }

  // Thyra view: one vector space per field, shared by the blocks of its row and column.
  Teuchos::Array<Teuchos::RCP<const Thyra::VectorSpaceBase<double>>> spaces;
  for (int f = 0; f < numFields; ++f) {
    I.spaces[f] = Thyra::tpetraVectorSpace<double>(I.maps[f]);
    spaces.push_back(I.spaces[f]);
  }
  I.product = Thyra::productVectorSpace<double>(spaces());
  auto op = Thyra::defaultBlockedLinearOp<double>();
  op->beginBlockFill(I.product, I.product);
  for (int bi = 0; bi < numFields; ++bi)
    for (int bj = 0; bj < numFields; ++bj)
      if (!I.blocks[bi][bj].is_null())
        op->setBlock(bi, bj,
                     Thyra::constTpetraLinearOp<double, LO, GO, Node>(
                         I.spaces[bi], I.spaces[bj],
                         Teuchos::rcp_implicit_cast<const Tpetra::Operator<double, LO, GO, Node>>(
                             I.blocks[bi][bj])));
  op->endBlockFill();
  I.op = op;
}

Teuchos::RCP<const Map> BlockSystem::monolithicMap() const
{
  return impl_->monolithic->getRowMap();
}

Teuchos::RCP<const Map> BlockSystem::fieldMap(int field) const { return impl_->maps.at(field); }

Teuchos::RCP<const CrsMatrix> BlockSystem::block(int row, int col) const
{
  return impl_->blocks.at(row).at(col);
}

Teuchos::RCP<const Thyra::LinearOpBase<double>> BlockSystem::blockedOperator() const
{
  return impl_->op;
}

Teuchos::RCP<const Thyra::ProductVectorSpaceBase<double>> BlockSystem::productSpace() const
{
  return impl_->product;
}

Teuchos::RCP<Thyra::MultiVectorBase<double>> BlockSystem::split(const MultiVector& x) const
{
  const auto& I = *impl_;
  SC_THROW_IF(x.getLocalLength() != monolithicMap()->getNodeNumElements(), core::InternalError,
              "BlockSystem::split: the vector has " << x.getLocalLength()
                                                    << " local entries, the monolithic map "
                                                    << monolithicMap()->getNodeNumElements());
  const std::size_t nv = x.getNumVectors();
  Teuchos::Array<Teuchos::RCP<Thyra::MultiVectorBase<double>>> parts;
  for (int f = 0; f < numFields; ++f) {
    auto xf = Teuchos::rcp(new MultiVector(I.maps[f], nv));
    const auto& idx = I.monolithicLocal[f];
    for (std::size_t k = 0; k < nv; ++k) {
      auto src = x.getData(k);
      auto dst = xf->getDataNonConst(k);
      for (std::size_t l = 0; l < idx.size(); ++l)
        dst[l] = src[idx[l]];
    }
    parts.push_back(Thyra::createMultiVector<double, LO, GO, Node>(xf, I.spaces[f]));
  }
  return Thyra::defaultProductMultiVector<double>(I.product, parts());
}

void BlockSystem::merge(const Thyra::MultiVectorBase<double>& blocked, MultiVector& x) const
{
  const auto& I = *impl_;
  const auto* p = dynamic_cast<const Thyra::ProductMultiVectorBase<double>*>(&blocked);
  SC_THROW_IF(!p || p->productSpace()->numBlocks() != numFields, core::InternalError,
              "BlockSystem::merge needs a product multivector of the 3 field spaces, got "
                  << blocked.description());
  SC_THROW_IF(x.getLocalLength() != monolithicMap()->getNodeNumElements() ||
                  static_cast<int>(x.getNumVectors()) != blocked.domain()->dim(),
              core::InternalError,
              "BlockSystem::merge: the monolithic vector has "
                  << x.getLocalLength() << " local rows and " << x.getNumVectors()
                  << " columns; expected " << monolithicMap()->getNodeNumElements() << " and "
                  << blocked.domain()->dim());
  for (int f = 0; f < numFields; ++f) {
    auto xf = Extract::getConstTpetraMultiVector(p->getMultiVectorBlock(f));
    const auto& idx = I.monolithicLocal[f];
    SC_THROW_IF(xf->getLocalLength() != idx.size(), core::InternalError,
                "BlockSystem::merge: block " << f << " has " << xf->getLocalLength()
                                             << " local rows, the field map " << idx.size());
    for (std::size_t k = 0; k < x.getNumVectors(); ++k) {
      auto src = xf->getData(k);
      auto dst = x.getDataNonConst(k);
      for (std::size_t l = 0; l < idx.size(); ++l)
        dst[idx[l]] = src[l];
    }
  }
}

}  // namespace sc::assembly
