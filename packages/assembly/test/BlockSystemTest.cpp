// The 3×3 block view (σ, u, θ) of the mixed elasticity system (BlockSystem, docs/architecture.md)
// against the monolithic matrix M it is cut from, at 1, 2 and 4 ranks: 2D (k = 1, 2) and 3D (k = 1)
// on the unstructured Gmsh meshes of the other assembly tests, with Dirichlet and traction data so
// that the traction rows eliminated in M are part of the blocks.
#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

#include <Teko_Utilities.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_UnitTestHarness.hpp>
#include <Thyra_LinearOpBase.hpp>
#include <Thyra_MultiVectorBase.hpp>
#include <Thyra_ProductVectorSpaceBase.hpp>
#include <Thyra_VectorSpaceBase.hpp>
#include <TpetraExt_MatrixMatrix.hpp>
#include <Tpetra_CrsMatrix.hpp>

#include <sc/assembly/BlockSystem.hpp>
#include <sc/assembly/MixedElasticitySystem.hpp>
#include <sc/core/Error.hpp>

#include <sc/testing/ElasticityTestProblem.hpp>

namespace {

using sc::assembly::BlockSystem;
using sc::assembly::CrsMatrix;
using sc::assembly::MixedElasticityAssembler;
using sc::assembly::MultiVector;

// docs/theory.md §"Mixed formulation": [[A, B1ᵀ, B2ᵀ], [B1, 0, 0], [B2, 0, 0]].
const std::pair<int, int> nonzeroBlocks[] = {{0, 0}, {0, 1}, {0, 2}, {1, 0}, {2, 0}};
const std::pair<int, int> couplingBlocks[] = {{0, 1}, {0, 2}, {1, 0}, {2, 0}};

struct AssembledProblem {
  std::unique_ptr<sc::assembly::MixedElasticitySystem> system;
  sc::core::Material material;
  const sc::disc::MixedElasticitySpace& space() const { return system->space(); }
  const MixedElasticityAssembler& assembler() const { return system->assembler(); }
};

/// The manufactured problem of ElasticityTestProblem.hpp (displacement on Left/Bottom(/Front),
/// traction on the other sides), assembled once by the application's pipeline. E = 1000 so that
/// 2μ ≠ 1 in the scaled checks.
AssembledProblem assemble(const std::string& source, int dim, double meshSize, int degree)
{
  auto comm = Teuchos::DefaultComm<int>::getComm();
  Teuchos::ParameterList meshList;
  meshList.set("Source", source);
  meshList.set("Initial mesh size", meshSize);
  meshList.set("Uniform refinements", 0);
  auto m = sc::mesh::MeshFactory::build(meshList, dim)->mesh();
  AssembledProblem p;
  p.material = sc::core::Material{1000.0, 0.3};
  p.system = std::make_unique<sc::assembly::MixedElasticitySystem>(m, degree, comm);
  auto exact = sc::core::createExactSolution("Manufactured smooth", dim, p.material);
  p.system->assemble({p.material, sc::test::verificationBoundaryConditions(dim), exact.get()});
  return p;
}

/// Expected field sizes from the dimensions of the element spaces (Boffi–Brezzi–Fortin 2013,
/// §2.3.1 and §2.5): RT_k has k+1 (2D) / (k+1)(k+2)/2 (3D) DOFs per face and k(k+1) (2D) /
/// k(k+1)(k+2)/2 (3D) interior DOFs per row; DP_k has dim P_k DOFs per element and component;
/// CP_k (k ≤ 2 here) has one DOF per vertex and k−1 per edge, per component. Independent of
/// the space's own numbering, so a lost or duplicated DOF fails here.
void expectedSizes(const sc::disc::MixedElasticitySpace& S, long long n[3])
{
  const auto& m = S.mesh();
  const long long k = S.degree(), d = S.dim();
  const long long faces = m.numFaces(), elements = m.numElements(), vertices = m.numVertices();
  const long long edges = d == 2 ? faces : m.numEdges();
  const long long rtFace = d == 2 ? k + 1 : (k + 1) * (k + 2) / 2;
  const long long rtInterior = d == 2 ? k * (k + 1) : k * (k + 1) * (k + 2) / 2;
  const long long pk = d == 2 ? (k + 1) * (k + 2) / 2 : (k + 1) * (k + 2) * (k + 3) / 6;
  n[0] = d * (rtFace * faces + rtInterior * elements);
  n[1] = d * pk * elements;
  n[2] = S.numRotationComponents() * (vertices + (k - 1) * edges);
}

double frobenius(const CrsMatrix& A) { return A.getFrobeniusNorm(); }

/// ‖Op(A) − B‖_F, Op = transpose or not.
double difference(const CrsMatrix& A, bool transposeA, const CrsMatrix& B)
{
  auto C = Tpetra::MatrixMatrix::add(1.0, transposeA, A, -1.0, false, B);
  return C->getFrobeniusNorm();
}

void checkBlockSystem(const AssembledProblem& p, Teuchos::FancyOStream& out, bool& success)
{
  const auto& S = p.space();
  const auto& M = *p.assembler().matrix();
  auto comm = M.getRowMap()->getComm();
  const double twoMu = 2.0 * p.material.shearModulus();
  BlockSystem plain(p.assembler());
  BlockSystem scaled(p.assembler(), twoMu);
  out << S.dim() << "D k=" << S.degree() << ": " << S.numGlobalDofs() << " DOFs ("
      << S.numStressDofs() << " σ, " << S.numDisplacementDofs() << " u, " << S.numRotationDofs()
      << " θ), " << M.getGlobalNumEntries() << " entries in M\n";

  // Sizes: field maps against the space's counts (source: MixedElasticitySpace) and against the
  // element-space dimensions (expectedSizes); blocks against the field maps.
  long long expected[3];
  expectedSizes(S, expected);
  const long long spaceCounts[3] = {S.numStressDofs(), S.numDisplacementDofs(),
                                    S.numRotationDofs()};
  long long sum = 0;
  std::size_t localSum = 0;
  for (int f = 0; f < 3; ++f) {
    const auto map = plain.fieldMap(f);
    TEST_EQUALITY(static_cast<long long>(map->getGlobalNumElements()), spaceCounts[f]);
    TEST_EQUALITY(spaceCounts[f], expected[f]);
    TEST_EQUALITY(map->getMinAllGlobalIndex(), 0LL);
    TEST_EQUALITY(map->getMaxAllGlobalIndex(), spaceCounts[f] - 1);
    TEST_ASSERT(map->isOneToOne());
    sum += static_cast<long long>(map->getGlobalNumElements());
    localSum += map->getNodeNumElements();
    for (int g = 0; g < 3; ++g) {
      auto B = plain.block(f, g);
      if (B.is_null()) continue;
      TEST_EQUALITY(static_cast<long long>(B->getRangeMap()->getGlobalNumElements()),
                    spaceCounts[f]);
      TEST_EQUALITY(static_cast<long long>(B->getDomainMap()->getGlobalNumElements()),
                    spaceCounts[g]);
      TEST_ASSERT(B->getRowMap()->isSameAs(*map));
    }
  }
  TEST_EQUALITY(sum, S.numGlobalDofs());
  TEST_EQUALITY(localSum, M.getRowMap()->getNodeNumElements());
  TEST_EQUALITY(sum, static_cast<long long>(plain.productSpace()->dim()));

  // Zero blocks: null here, null in the Thyra operator (Teko::isZeroOp), and M holds only
  // exact zeros there (source: MixedElasticityAssembler::assemble adds to (σ,·) and (·,σ)
  // entries only). The entries of the five other blocks plus M's entries in the zero blocks are
  // all of M's entries (nothing dropped or duplicated).
  auto blocked = Teko::toBlockedLinearOp(plain.blockedOperator());
  TEST_ASSERT(!blocked.is_null());
  for (int f = 1; f < 3; ++f)
    for (int g = 1; g < 3; ++g) {
      TEST_ASSERT(plain.block(f, g).is_null());
      TEST_ASSERT(Teko::isZeroOp(Teko::getBlock(f, g, blocked)));
    }
  bool allBlocks = true;
  for (const auto& [f, g] : nonzeroBlocks) {
    TEST_ASSERT(!Teko::isZeroOp(Teko::getBlock(f, g, blocked)));
    allBlocks = allBlocks && !plain.block(f, g).is_null() && !scaled.block(f, g).is_null();
  }
  TEST_ASSERT(allBlocks);
  if (!allBlocks) return;  // the checks below read the five blocks
  double maxZeroBlock = 0.0;
  long long zeroBlockEntries = 0;
  {
    const auto& layout = plain.layout();
    const auto& rowMap = *M.getRowMap();
    const auto& colMap = *M.getColMap();
    CrsMatrix::local_inds_host_view_type cols;
    CrsMatrix::values_host_view_type vals;
    for (std::size_t r = 0; r < rowMap.getNodeNumElements(); ++r) {
      if (layout.fieldOf(rowMap.getGlobalElement(r)) == 0) continue;
      M.getLocalRowView(r, cols, vals);
      for (std::size_t k = 0; k < cols.extent(0); ++k)
        if (layout.fieldOf(colMap.getGlobalElement(cols(k))) != 0) {
          maxZeroBlock = std::max(maxZeroBlock, std::abs(vals(k)));
          ++zeroBlockEntries;
        }
    }
  }
  double maxZeroBlockAll = 0.0;
  long long zeroBlockEntriesAll = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, maxZeroBlock, Teuchos::outArg(maxZeroBlockAll));
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, zeroBlockEntries,
                     Teuchos::outArg(zeroBlockEntriesAll));
  TEST_EQUALITY(maxZeroBlockAll, 0.0);
  long long blockEntries = 0;
  for (const auto& [f, g] : nonzeroBlocks)
    blockEntries += static_cast<long long>(plain.block(f, g)->getGlobalNumEntries());
  TEST_EQUALITY(blockEntries + zeroBlockEntriesAll,
                static_cast<long long>(M.getGlobalNumEntries()));

  // B1 = (B1ᵀ)ᵀ and B2 = (B2ᵀ)ᵀ to round-off: M is assembled symmetrically (docs/theory.md §"Mixed
  // formulation": the matrix without contact is symmetric), only the order of the cross-rank sums
  // may differ.
  for (int f = 1; f < 3; ++f) {
    const double diff = difference(*plain.block(0, f), true, *plain.block(f, 0));
    const double norm = frobenius(*plain.block(f, 0));
    out << "  |B" << f << " - (B" << f << "ᵀ)ᵀ|_F / |B" << f << "|_F = " << diff / norm << "\n";
    TEST_COMPARE(norm, >, 0.0);
    TEST_COMPARE(diff, <=, 1e-14 * norm);
  }
  // The scaled system is D M D: A times 2μ, B1 and B2 unchanged (MixedElasticityAssembler::
  // physicalScaling: √(2μ) on σ, 1/√(2μ) on u and θ).
  {
    const double diffA = difference(*scaled.block(0, 0), false, *plain.block(0, 0));
    out << "  2μ = " << twoMu
        << ", |A_scaled − A|_F / |A|_F = " << diffA / frobenius(*plain.block(0, 0))
        << " (expected |2μ − 1| = " << std::abs(twoMu - 1.0) << ")\n";
    TEST_FLOATING_EQUALITY(diffA / frobenius(*plain.block(0, 0)), std::abs(twoMu - 1.0), 1e-12);
    for (const auto& [f, g] : couplingBlocks)
      TEST_EQUALITY(difference(*scaled.block(f, g), false, *plain.block(f, g)), 0.0);
  }

  // Products: Op x against merge(Blocked · split(x)) for random x (3 columns), Op = M and
  // Op = D M D; merge(split(x)) = x exactly.
  const auto map = M.getRowMap();
  MultiVector x(map, 3), y(map, 3), z(map, 3), back(map, 3);
  x.randomize();
  plain.merge(*plain.split(x), back);
  back.update(-1.0, x, 1.0);
  Teuchos::Array<double> norms(3), ref(3);
  back.normInf(norms());
  for (double v : norms)
    TEST_EQUALITY(v, 0.0);
  const auto D = p.assembler().physicalScaling(twoMu)->getVector(0);
  for (const BlockSystem* bs : {&plain, &scaled}) {
    const bool isScaled = bs == &scaled;
    MultiVector xs(x, Teuchos::Copy);
    if (isScaled) xs.elementWiseMultiply(1.0, *D, x, 0.0);
    M.apply(xs, y);
    if (isScaled) {
      MultiVector t(y, Teuchos::Copy);
      y.elementWiseMultiply(1.0, *D, t, 0.0);
    }
    auto xb = bs->split(x);
    auto yb = Thyra::createMembers(bs->blockedOperator()->range(), 3);
    Thyra::apply(*bs->blockedOperator(), Thyra::NOTRANS, *xb, yb.ptr());
    bs->merge(*yb, z);
    z.update(-1.0, y, 1.0);
    z.norm2(norms());
    y.norm2(ref());
    for (int j = 0; j < 3; ++j) {
      out << "  " << (isScaled ? "D M D" : "M") << ", column " << j
          << ": |Op x − merge(Blocked·split(x))| / |Op x| = " << norms[j] / ref[j] << "\n";
      TEST_COMPARE(ref[j], >, 0.0);
      TEST_COMPARE(norms[j], <=, 1e-13 * ref[j]);
    }
  }
}

}  // namespace

TEUCHOS_UNIT_TEST(BlockSystem, MatchesMonolithic2D)
{
  for (int k : {1, 2})
    checkBlockSystem(assemble("Unit square", 2, 0.3, k), out, success);
}

TEUCHOS_UNIT_TEST(BlockSystem, MatchesMonolithic3D)
{
  checkBlockSystem(assemble("Unit cube", 3, 0.5, 1), out, success);
}

// A monolithic matrix with a non-zero value in a zero block (here uu, on rank 0 only) is refused
// on every rank rather than cut silently (BlockSystem's FieldLayout constructor).
TEUCHOS_UNIT_TEST(BlockSystem, RefusesNonZeroZeroBlock)
{
  auto p = assemble("Unit square", 2, 0.3, 1);
  const auto& S = p.space();
  const sc::assembly::FieldLayout layout{S.numStressDofs(), S.numDisplacementDofs(),
                                         S.numRotationDofs()};
  auto M = Teuchos::rcp(new CrsMatrix(*p.assembler().matrix(), Teuchos::Copy));
  TEST_NOTHROW(BlockSystem accepted(M, layout));
  M->resumeFill();
  bool changed = false;
  const auto& rowMap = *M->getRowMap();
  const auto& colMap = *M->getColMap();
  if (rowMap.getComm()->getRank() == 0) {
    CrsMatrix::local_inds_host_view_type cols;
    CrsMatrix::values_host_view_type vals;
    for (std::size_t r = 0; r < rowMap.getNodeNumElements() && !changed; ++r) {
      if (layout.fieldOf(rowMap.getGlobalElement(r)) != 1) continue;
      M->getLocalRowView(r, cols, vals);
      for (std::size_t k = 0; k < cols.extent(0) && !changed; ++k)
        if (layout.fieldOf(colMap.getGlobalElement(cols(k))) == 1) {
          const int c = cols(k);
          const double one = 1.0;
          M->replaceLocalValues(static_cast<int>(r), Teuchos::ArrayView<const int>(&c, 1),
                                Teuchos::ArrayView<const double>(&one, 1));
          changed = true;
        }
    }
    TEST_ASSERT(changed);  // DG displacements: every u row has its uu diagonal in the graph
  }
  M->fillComplete(M->getDomainMap(), M->getRangeMap());
  TEST_THROW(BlockSystem refused(M, layout), sc::core::InternalError);
}
