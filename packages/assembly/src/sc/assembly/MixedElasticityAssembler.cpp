#include "sc/assembly/MixedElasticityAssembler.hpp"

#include <algorithm>
#include <cmath>

#include <Teuchos_Time.hpp>
#include <Kokkos_Core.hpp>
#include <Tpetra_CrsGraph.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_MultiVector.hpp>

#include <sc/assembly/LoadsAndSupports.hpp>
#include <sc/core/Error.hpp>
#include <sc/disc/ElementValues.hpp>
#include <sc/disc/MixedElasticitySpace.hpp>
#include <sc/mesh/SimplexMesh.hpp>

namespace sc::assembly {
namespace {

using Graph = Tpetra::CrsGraph<>;
using GO = Tpetra::Map<>::global_ordinal_type;
using LO = Tpetra::Map<>::local_ordinal_type;

// Solve the small dense system M c = r (Gaussian elimination with partial pivoting).
void solveDense(std::vector<double> M, std::vector<double>& r, int n)
{
  for (int k = 0; k < n; ++k) {
    int p = k;
    for (int i = k + 1; i < n; ++i)
      if (std::abs(M[i * n + k]) > std::abs(M[p * n + k])) p = i;
    SC_THROW_IF(std::abs(M[p * n + k]) < 1e-300, core::InternalError,
                "singular face mass matrix in the traction projection");
    if (p != k) {
      for (int j = 0; j < n; ++j)
        std::swap(M[k * n + j], M[p * n + j]);
      std::swap(r[k], r[p]);
    }
    for (int i = k + 1; i < n; ++i) {
      const double f = M[i * n + k] / M[k * n + k];
      for (int j = k; j < n; ++j)
        M[i * n + j] -= f * M[k * n + j];
      r[i] -= f * r[k];
    }
  }
  for (int k = n - 1; k >= 0; --k) {
    for (int j = k + 1; j < n; ++j)
      r[k] -= M[k * n + j] * r[j];
    r[k] /= M[k * n + k];
  }
}

// The face DOFs of one RT function φ_l on a face in the normal–tangential frame: slot[i] is the
// element-local DOF of stress row i (its coefficient s_i, so that σn = Σ_l s_l (φ_l·n) on the
// face), and R the orthogonal matrix whose row p, stored in slot[p], is the direction of the
// frame component w_p = R_p·s: the normal n in the slot of the row a = argmax |n_a|, tangents in
// the others (docs/theory.md §"Loads and supports").
struct FrameTuple {
  int slot[3] = {0, 0, 0};
  double R[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
};

// The frame of the outward unit normal n: row a = argmax |n_c| is n, the others unit tangents
// (e_b and ±e_c exactly when n = ±e_a).
void normalFrame(const double* n, int d, int& a, double R[3][3])
{
  a = 0;
  for (int c = 1; c < d; ++c)
    if (std::abs(n[c]) > std::abs(n[a])) a = c;
  for (int c = 0; c < d; ++c)
    R[a][c] = n[c];
  if (d == 2) {
    const int b = 1 - a;
    R[b][0] = -n[1], R[b][1] = n[0];
    return;
  }
  const int b = (a + 1) % 3, c2 = (a + 2) % 3;
  double t1[3] = {0, 0, 0};
  t1[b] = 1.0;
  for (int c = 0; c < 3; ++c)
    t1[c] -= n[b] * n[c];
  const double norm = std::sqrt(t1[0] * t1[0] + t1[1] * t1[1] + t1[2] * t1[2]);
  for (int c = 0; c < 3; ++c)
    R[b][c] = t1[c] / norm;
  R[c2][0] = n[1] * R[b][2] - n[2] * R[b][1];
  R[c2][1] = n[2] * R[b][0] - n[0] * R[b][2];
  R[c2][2] = n[0] * R[b][1] - n[1] * R[b][0];
}

// K ← M K Mᵀ and F ← M F on the slots of each tuple (M = R: to the frame; M = Rᵀ: back).
void transformFrames(std::vector<double>& K, std::vector<double>& F, int L, int d,
                     const std::vector<FrameTuple>& tuples, bool transpose)
{
  auto M = [&](const FrameTuple& t, int p, int i) { return transpose ? t.R[i][p] : t.R[p][i]; };
  double tmp[3];
  for (const auto& t : tuples) {
    for (int j = 0; j < L; ++j) {  // rows
      for (int p = 0; p < d; ++p) {
        tmp[p] = 0.0;
        for (int i = 0; i < d; ++i)
          tmp[p] += M(t, p, i) * K[static_cast<std::size_t>(t.slot[i]) * L + j];
      }
      for (int p = 0; p < d; ++p)
        K[static_cast<std::size_t>(t.slot[p]) * L + j] = tmp[p];
    }
    for (int j = 0; j < L; ++j) {  // columns
      for (int p = 0; p < d; ++p) {
        tmp[p] = 0.0;
        for (int i = 0; i < d; ++i)
          tmp[p] += M(t, p, i) * K[static_cast<std::size_t>(j) * L + t.slot[i]];
      }
      for (int p = 0; p < d; ++p)
        K[static_cast<std::size_t>(j) * L + t.slot[p]] = tmp[p];
    }
    for (int p = 0; p < d; ++p) {
      tmp[p] = 0.0;
      for (int i = 0; i < d; ++i)
        tmp[p] += M(t, p, i) * F[t.slot[i]];
    }
    for (int p = 0; p < d; ++p)
      F[t.slot[p]] = tmp[p];
  }
}

}  // namespace

const std::vector<AsymmetryTerm>& asymmetryTerms(int dim)
{
  static const std::vector<AsymmetryTerm> terms2D = {{0, 0, 1, 1.0}, {0, 1, 0, -1.0}};
  static const std::vector<AsymmetryTerm> terms3D = {{0, 2, 1, 1.0}, {0, 1, 2, -1.0},
                                                     {1, 0, 2, 1.0}, {1, 2, 0, -1.0},
                                                     {2, 1, 0, 1.0}, {2, 0, 1, -1.0}};
  return dim == 2 ? terms2D : terms3D;
}

// The matrix holds this rank's owned rows only, complete: each rank assembles, besides its own
// elements, the elements of other ranks that touch its rows (the mesh is replicated), and keeps
// the rows it owns. The graph is built once per space from local CSR arrays with a precomputed
// column map (no global index insertion, no global-to-local conversion, no export of shared
// rows) and reused by every assembly on the space (docs/theory.md §"Parallel model").
struct MixedElasticityAssembler::Impl {
  Teuchos::RCP<const Map> owned, overlap, columns;
  Teuchos::RCP<const Graph> graph;
  Teuchos::RCP<CrsMatrix> matrix;
  Teuchos::RCP<MultiVector> rhs;
  Teuchos::RCP<const Tpetra::Import<>> importer;  // owned -> overlap
  Teuchos::RCP<CrsMatrix> fieldMass;              // cached by fieldMassMatrix()
  // The elements that touch an owned row (ascending), whether this rank owns each, and their
  // DOFs' local column indices (localSize() per element). An owned DOF's column index is its row
  // index: the column map lists the owned DOFs first, in the owned map's order.
  std::vector<int> elements;
  std::vector<char> ownsElement;
  std::vector<LO> elementColumns;
  LO numOwned = 0;

  // Sum the element matrix K (L×L, row-major) and vector F (optional) into the owned rows.
  void sumInto(std::size_t k, int L, const double* K, const double* F) const
  {
    const LO* cols = &elementColumns[k * static_cast<std::size_t>(L)];
    for (int i = 0; i < L; ++i) {
      if (cols[i] >= numOwned) continue;
      matrix->sumIntoLocalValues(cols[i], L, &K[static_cast<std::size_t>(i) * L], cols, false);
      if (F) rhs->sumIntoLocalValue(cols[i], 0, F[i]);
    }
  }
};

MixedElasticityAssembler::MixedElasticityAssembler(
    Teuchos::RCP<const disc::MixedElasticitySpace> space,
    Teuchos::RCP<const Teuchos::Comm<int>> comm)
    : space_(std::move(space)), comm_(std::move(comm)), impl_(std::make_unique<Impl>())
{
  buildGraph();
}

MixedElasticityAssembler::~MixedElasticityAssembler() = default;

void MixedElasticityAssembler::buildGraph()
{
  const double t0 = Teuchos::Time::wallTime();
  const auto& S = *space_;
  Impl& I = *impl_;
  const GO n = S.numGlobalDofs();
  const int me = S.rank();
  const int L = S.localSize();
  const auto& ownedDofs = S.ownedDofs();
  const auto nOwned = static_cast<LO>(ownedDofs.size());
  I.numOwned = nOwned;

  // The overlap map (owned DOFs first, then the other DOFs of this rank's elements) and its
  // importer; the owners of the remote DOFs are known, so the importer needs no directory.
  std::vector<GO> overlapGids(ownedDofs.begin(), ownedDofs.end());
  Teuchos::Array<int> overlapOwners;
  for (long long g : S.overlapDofs())
    if (S.dofOwner(g) != me) {
      overlapGids.push_back(g);
      overlapOwners.push_back(S.dofOwner(g));
    }
  I.owned = Teuchos::rcp(
      new Map(n, Teuchos::ArrayView<const GO>(ownedDofs.data(), ownedDofs.size()), 0, comm_));
  I.overlap = Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                                   Teuchos::ArrayView<const GO>(overlapGids), 0, comm_));
  I.importer = Teuchos::rcp(new Tpetra::Import<>(I.owned, I.overlap, overlapOwners));

  // Column indices: the owned DOFs in the owned map's order, then the other DOFs of the elements
  // that touch owned rows, by owning rank and then global index (the order Tpetra's own column
  // map construction gives).
  std::vector<LO> column(static_cast<std::size_t>(n), -1);
  for (LO i = 0; i < nOwned; ++i)
    column[static_cast<std::size_t>(ownedDofs[i])] = i;
  const int nElements = S.mesh().numElements();
  std::vector<char> owns(static_cast<std::size_t>(nElements), 0);
  for (int e : S.ownedElements())
    owns[e] = 1;
  I.elements.clear();
  I.ownsElement.clear();
  std::vector<std::pair<int, GO>> remote;  // (owner, gid)
  for (int e = 0; e < nElements; ++e) {
    const long long* g = S.elementDofs(e);
    bool touches = owns[e] != 0;
    for (int i = 0; i < L && !touches; ++i) {
      const LO c = column[static_cast<std::size_t>(g[i])];
      touches = c >= 0 && c < nOwned;
    }
    if (!touches) continue;
    I.elements.push_back(e);
    I.ownsElement.push_back(owns[e]);
    for (int i = 0; i < L; ++i)
      if (column[static_cast<std::size_t>(g[i])] == -1) {
        column[static_cast<std::size_t>(g[i])] = -2;
        remote.emplace_back(S.dofOwner(g[i]), g[i]);
      }
  }
  std::sort(remote.begin(), remote.end());
  std::vector<GO> columnGids(ownedDofs.begin(), ownedDofs.end());
  Teuchos::Array<int> columnOwners;
  columnGids.reserve(ownedDofs.size() + remote.size());
  columnOwners.reserve(remote.size());
  for (std::size_t r = 0; r < remote.size(); ++r) {
    column[static_cast<std::size_t>(remote[r].second)] = nOwned + static_cast<LO>(r);
    columnGids.push_back(remote[r].second);
    columnOwners.push_back(remote[r].first);
  }
  const auto nColumns = static_cast<LO>(columnGids.size());
  I.columns = Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                                   Teuchos::ArrayView<const GO>(columnGids), 0, comm_));
  const std::size_t nAssembled = I.elements.size();
  I.elementColumns.resize(nAssembled * L);
  for (std::size_t k = 0; k < nAssembled; ++k) {
    const long long* g = S.elementDofs(I.elements[k]);
    for (int i = 0; i < L; ++i)
      I.elementColumns[k * L + i] = column[static_cast<std::size_t>(g[i])];
  }
  std::vector<LO>().swap(column);

  // The elements around each owned row, then each row's columns: the union of their DOFs
  // (counted, then filled, with a last-row marker per column), sorted.
  std::vector<LO> rowStart(static_cast<std::size_t>(nOwned) + 1, 0);
  for (LO c : I.elementColumns)
    if (c < nOwned) ++rowStart[c + 1];
  for (LO r = 0; r < nOwned; ++r)
    rowStart[r + 1] += rowStart[r];
  std::vector<LO> rowElements(static_cast<std::size_t>(rowStart[nOwned]));
  {
    std::vector<LO> fill(rowStart.begin(), rowStart.end() - 1);
    for (std::size_t k = 0; k < nAssembled; ++k)
      for (int i = 0; i < L; ++i) {
        const LO c = I.elementColumns[k * L + i];
        if (c < nOwned) rowElements[fill[c]++] = static_cast<LO>(k);
      }
  }
  using LocalGraph = Graph::local_graph_device_type;
  typename LocalGraph::row_map_type::non_const_type rowPointers(
      Kokkos::view_alloc("row pointers", Kokkos::WithoutInitializing),
      static_cast<std::size_t>(nOwned) + 1);
  auto rowPointersHost = Kokkos::create_mirror_view(rowPointers);
  std::vector<LO> marker(static_cast<std::size_t>(nColumns), -1);
  rowPointersHost(0) = 0;
  for (LO r = 0; r < nOwned; ++r) {
    std::size_t count = 0;
    for (LO k = rowStart[r]; k < rowStart[r + 1]; ++k) {
      const LO* cols = &I.elementColumns[static_cast<std::size_t>(rowElements[k]) * L];
      for (int i = 0; i < L; ++i)
        if (marker[cols[i]] != r) {
          marker[cols[i]] = r;
          ++count;
        }
    }
    rowPointersHost(r + 1) = rowPointersHost(r) + count;
  }
  typename LocalGraph::entries_type::non_const_type entries(
      Kokkos::view_alloc("column indices", Kokkos::WithoutInitializing), rowPointersHost(nOwned));
  auto entriesHost = Kokkos::create_mirror_view(entries);
  std::fill(marker.begin(), marker.end(), -1);
  for (LO r = 0; r < nOwned; ++r) {
    std::size_t pos = rowPointersHost(r);
    for (LO k = rowStart[r]; k < rowStart[r + 1]; ++k) {
      const LO* cols = &I.elementColumns[static_cast<std::size_t>(rowElements[k]) * L];
      for (int i = 0; i < L; ++i)
        if (marker[cols[i]] != r) {
          marker[cols[i]] = r;
          entriesHost(pos++) = cols[i];
        }
    }
    std::sort(&entriesHost(rowPointersHost(r)), &entriesHost(0) + pos);
  }
  Kokkos::deep_copy(rowPointers, rowPointersHost);
  Kokkos::deep_copy(entries, entriesHost);
  auto columnImporter = Teuchos::rcp(new Tpetra::Import<>(I.owned, I.columns, columnOwners));
  I.graph = Teuchos::rcp(new Graph(LocalGraph(entries, rowPointers), I.owned, I.columns, I.owned,
                                   I.owned, columnImporter, Teuchos::null));
  I.matrix = Teuchos::rcp(new CrsMatrix(I.graph));
  I.rhs = Teuchos::rcp(new MultiVector(I.owned, 1));
  stats_.graphSeconds = Teuchos::Time::wallTime() - t0;
  stats_.ownedElements = static_cast<long long>(S.ownedElements().size());
  stats_.nonzeros = static_cast<long long>(I.graph->getGlobalNumEntries());
}

void MixedElasticityAssembler::assemble(const ElasticityData& data)
{
  const double t0 = Teuchos::Time::wallTime();
  const auto& S = *space_;
  const auto& m = S.mesh();
  const int d = S.dim(), k = S.degree(), L = S.localSize();
  const int nRT = S.stressBasisSize(), nDP = S.displacementBasisSize(), nCP = S.rotationBasisSize();
  const double inv2mu = 1.0 / (2.0 * data.material.shearModulus());
  const double cd = data.material.complianceCoefficient(d);
  const core::ExactSolution* exact = data.exactSolution;
  for (const auto& bc : data.boundaryConditions.conditions) {
    SC_THROW_IF(bc.fromExactSolution && !exact, core::InputError,
                "'Boundary Conditions/" << bc.boundary << "/Data' = 'Exact solution', but "
                                        << "'Problem/Exact solution' is 'None'.");
  }
  const bool bodyForce = data.hasBodyForce();
  // The same on every rank (replicated mesh): a bad Symmetry part fails on all ranks together.
  const auto frameParts = normalFrameParts(m, data.boundaryConditions);
  std::vector<FrameTuple> frames;

  disc::ElementValues ev(S, 2 * k + 2);
  disc::FaceValues fv(S, 2 * k + 2);
  std::vector<double> K(static_cast<std::size_t>(L) * L), F(L);
  std::vector<double> G(static_cast<std::size_t>(nRT) * nRT);
  std::vector<double> P(static_cast<std::size_t>(d) * d * nRT * nRT);
  std::vector<char> constrained(L);
  std::vector<double> constrainedValue(L);
  long long nConstrained = 0;

  auto& A = *impl_->matrix;
  auto& b = *impl_->rhs;
  if (A.isFillComplete()) A.resumeFill();
  A.setAllToScalar(0.0);
  b.putScalar(0.0);

  const auto& elements = impl_->elements;
  for (std::size_t ek = 0; ek < elements.size(); ++ek) {
    const int e = elements[ek];
    std::fill(K.begin(), K.end(), 0.0);
    std::fill(F.begin(), F.end(), 0.0);
    std::fill(G.begin(), G.end(), 0.0);
    std::fill(P.begin(), P.end(), 0.0);
    std::fill(constrained.begin(), constrained.end(), 0);
    frames.clear();
    ev.reinit(e);
    auto KK = [&](int i, int j) -> double& { return K[static_cast<std::size_t>(i) * L + j]; };
    for (int q = 0; q < ev.numPoints(); ++q) {
      const double w = ev.weight(q);
      for (int a = 0; a < nRT; ++a)
        for (int bb = 0; bb < nRT; ++bb) {
          double dot = 0.0;
          for (int c = 0; c < d; ++c)
            dot += ev.stress(a, q, c) * ev.stress(bb, q, c);
          G[a * nRT + bb] += w * dot;
          for (int i = 0; i < d; ++i)
            for (int j = 0; j < d; ++j)
              P[((i * d + j) * nRT + a) * nRT + bb] += w * ev.stress(a, q, i) * ev.stress(bb, q, j);
        }
      // B1: (div σ_i, v_i); B2: (as σ, η).
      for (int a = 0; a < nDP; ++a)
        for (int bb = 0; bb < nRT; ++bb) {
          const double v = w * ev.displacement(a, q) * ev.stressDiv(bb, q);
          for (int i = 0; i < d; ++i) {
            KK(S.displacementOffset(i) + a, S.stressOffset(i) + bb) += v;
            KK(S.stressOffset(i) + bb, S.displacementOffset(i) + a) += v;
          }
        }
      for (int a = 0; a < nCP; ++a)
        for (int bb = 0; bb < nRT; ++bb) {
          const double eta = w * ev.rotation(a, q);
          for (const auto& t : asymmetryTerms(d)) {
            const double v = t.sign * eta * ev.stress(bb, q, t.col);
            KK(S.rotationOffset(t.comp) + a, S.stressOffset(t.row) + bb) += v;
            KK(S.stressOffset(t.row) + bb, S.rotationOffset(t.comp) + a) += v;
          }
        }
      if (bodyForce) {
        double f[3];
        data.bodyForceAt(ev.point(q), d, f);
        for (int i = 0; i < d; ++i)
          for (int a = 0; a < nDP; ++a)
            F[S.displacementOffset(i) + a] -= w * f[i] * ev.displacement(a, q);
      }
    }
    // A: (1/2μ)[δ_ij (φ_a, φ_b) − c_d (φ_a[i], φ_b[j])].
    for (int i = 0; i < d; ++i)
      for (int j = 0; j < d; ++j)
        for (int a = 0; a < nRT; ++a)
          for (int bb = 0; bb < nRT; ++bb)
            KK(S.stressOffset(i) + a, S.stressOffset(j) + bb) +=
                inv2mu *
                ((i == j ? G[a * nRT + bb] : 0.0) - cd * P[((i * d + j) * nRT + a) * nRT + bb]);

    // Boundary faces: natural u_D, essential t (projected; −p n for a pressure), free (t = 0),
    // Symmetry / Normal displacement (the tangential components zero) and Components (each
    // row natural or essential).
    const int* faces = m.elementFaces(e);
    for (int lf = 0; lf <= d; ++lf) {
      const int f = faces[lf];
      if (!m.isBoundaryFace(f)) continue;
      const core::BoundaryCondition* bc =
          data.boundaryConditions.find(m.boundaryName(m.faceBoundaryId(f)));
      const core::BoundaryType type = bc ? bc->type : core::BoundaryType::Free;
      const auto& faceDofs = S.stressFaceLocalDofs(lf);
      const int nF = static_cast<int>(faceDofs.size());
      // Contact: no term here. ⟨ũ, τn⟩_ΓC is the residual of these rows, which the contact package
      // (ActiveSetSolver) turns into the contact conditions (docs/theory.md §"Contact and
      // friction").
      if (type == core::BoundaryType::Contact) continue;
      if (type == core::BoundaryType::Displacement) {
        fv.reinit(e, lf);
        for (int q = 0; q < fv.numPoints(); ++q) {
          double uD[3] = {0, 0, 0};
          bc->evaluate(fv.point(q), fv.normal(q).data(), d, exact, uD);
          for (int i = 0; i < d; ++i)
            for (int a : faceDofs)
              F[S.stressOffset(i) + a] += fv.weight(q) * uD[i] * fv.stressNormal(a, q);
        }
        continue;
      }
      // Symmetry (g = 0) and Normal displacement on a flat part with the outward normal n: in
      // the frame w = R s of each face DOF's row coefficients the tangential components are zero
      // (essential, σn ∥ n) and the normal one is free, with the natural data ⟨g, τ·n⟩, the
      // load of u_D = g n (docs/theory.md §"Loads and supports"). Axis-normal parts: R is a
      // signed permutation and this is the elimination of the rows i ≠ a.
      if (bc && bc->inNormalFrame()) {
        const double* n = frameParts.at(bc->boundary).normal.data();
        if (S.isCurved(e)) {
          // A curved element's face on the part must still be flat (its normal n everywhere).
          fv.reinit(e, lf);
          for (int q = 0; q < fv.numPoints(); ++q) {
            double dev = 0.0;
            for (int c = 0; c < d; ++c)
              dev += std::pow(fv.normal(q)[c] - n[c], 2);
            SC_THROW_IF(std::sqrt(dev) > 1e-9, core::InputError,
                        "'Boundary Conditions/"
                            << bc->boundary << "/Type' = '" << core::toString(bc->type)
                            << "' needs a flat part, but '" << bc->boundary
                            << "' is curved (its quadratic faces, Mesh/Geometry "
                            << "order = 2, turn their normal by " << std::sqrt(dev) << " rad): "
                            << "conditions in the normal–tangential frame of curved parts are "
                            << "not supported (docs/theory.md §\"Loads and supports\").");
          }
        }
        if (type == core::BoundaryType::NormalDisplacement && !bc->isZero()) {
          fv.reinit(e, lf);
          for (int q = 0; q < fv.numPoints(); ++q) {
            double uD[3] = {0, 0, 0};
            bc->evaluate(fv.point(q), n, d, exact, uD);
            for (int i = 0; i < d; ++i)
              for (int a : faceDofs)
                F[S.stressOffset(i) + a] += fv.weight(q) * uD[i] * fv.stressNormal(a, q);
          }
        }
        int a = 0;
        FrameTuple t;
        normalFrame(n, d, a, t.R);
        for (int l = 0; l < nF; ++l) {
          for (int i = 0; i < d; ++i) {
            t.slot[i] = S.stressOffset(i) + faceDofs[l];
            if (i != a) {
              constrained[t.slot[i]] = 1;
              constrainedValue[t.slot[i]] = 0.0;
            }
          }
          frames.push_back(t);
        }
        continue;
      }
      // Traction, pressure or free: σ_i·n = t_i on the face, as the L² projection onto the
      // normal traces of the face DOFs (only these have a non-zero normal trace on the face).
      // A pressure's t = −p n follows the face's normal at each quadrature point, which varies
      // on a curved face. Components (global frame, any face): row i is essential like this
      // when component i is a traction, and natural like a Displacement part's when it is a
      // displacement (the load ⟨g_i, τ_i·n⟩); no frame is needed (docs/theory.md §"Loads and
      // supports").
      bool essentialRow[3] = {true, true, true};
      for (int i = 0; i < d; ++i)
        essentialRow[i] = !(bc && bc->displacementComponent(i));
      std::vector<double> values(static_cast<std::size_t>(d) * nF, 0.0);
      const bool zero = type == core::BoundaryType::Free || bc->isZero();
      if (!zero) {
        fv.reinit(e, lf);
        std::vector<double> M(static_cast<std::size_t>(nF) * nF, 0.0);
        std::vector<std::vector<double>> rhs(d, std::vector<double>(nF, 0.0));
        for (int q = 0; q < fv.numPoints(); ++q) {
          double t[3] = {0, 0, 0};
          bc->evaluate(fv.point(q), fv.normal(q).data(), d, exact, t);
          for (int l = 0; l < nF; ++l) {
            const double pl = fv.stressNormal(faceDofs[l], q);
            for (int j = 0; j < nF; ++j)
              M[l * nF + j] += fv.weight(q) * pl * fv.stressNormal(faceDofs[j], q);
            for (int i = 0; i < d; ++i)
              if (essentialRow[i])
                rhs[i][l] += fv.weight(q) * t[i] * pl;
              else
                F[S.stressOffset(i) + faceDofs[l]] += fv.weight(q) * t[i] * pl;
          }
        }
        for (int i = 0; i < d; ++i) {
          if (!essentialRow[i]) continue;
          solveDense(M, rhs[i], nF);
          for (int l = 0; l < nF; ++l)
            values[i * nF + l] = rhs[i][l];
        }
      }
      for (int i = 0; i < d; ++i)
        for (int l = 0; l < nF; ++l) {
          if (!essentialRow[i]) continue;
          const int c = S.stressOffset(i) + faceDofs[l];
          constrained[c] = 1;
          constrainedValue[c] = values[i * nF + l];
        }
    }
    // Symmetric elimination of the constrained DOFs, with a diagonal of the A block's size; the
    // normal-frame faces' DOFs in their frame during it.
    transformFrames(K, F, L, d, frames, false);
    double diag = 0.0;
    int nd = 0;
    for (int i = 0; i < d * nRT; ++i)
      if (!constrained[i]) {
        diag += std::abs(KK(i, i));
        ++nd;
      }
    diag = nd ? diag / nd : inv2mu;
    for (int c = 0; c < L; ++c) {
      if (!constrained[c]) continue;
      if (impl_->ownsElement[ek]) ++nConstrained;
      const double g = constrainedValue[c];
      for (int i = 0; i < L; ++i) {
        if (i != c) F[i] -= KK(i, c) * g;
        KK(i, c) = 0.0;
        KK(c, i) = 0.0;
      }
      KK(c, c) = diag;
      F[c] = diag * g;
    }
    transformFrames(K, F, L, d, frames, true);
    impl_->sumInto(ek, L, K.data(), F.data());
  }
  A.fillComplete(impl_->owned, impl_->owned);
  impl_->fieldMass = Teuchos::null;
  stats_.constrainedDofs = nConstrained;
  stats_.assemblySeconds = Teuchos::Time::wallTime() - t0;
}

Teuchos::RCP<const CrsMatrix> MixedElasticityAssembler::fieldMassMatrix() const
{
  if (!impl_->fieldMass.is_null()) return impl_->fieldMass;
  const auto& S = *space_;
  const int d = S.dim(), k = S.degree(), L = S.localSize();
  const int nDP = S.displacementBasisSize(), nCP = S.rotationBasisSize();
  const int r = S.numRotationComponents();
  disc::ElementValues ev(S, 2 * k + 2);
  auto M = Teuchos::rcp(new CrsMatrix(impl_->graph));
  std::vector<double> K(static_cast<std::size_t>(L) * L);
  M->setAllToScalar(0.0);
  const auto& elements = impl_->elements;
  for (std::size_t ek = 0; ek < elements.size(); ++ek) {
    const int e = elements[ek];
    std::fill(K.begin(), K.end(), 0.0);
    ev.reinit(e);
    for (int q = 0; q < ev.numPoints(); ++q) {
      const double w = ev.weight(q);
      for (int a = 0; a < nDP; ++a)
        for (int bb = 0; bb < nDP; ++bb) {
          const double v = w * ev.displacement(a, q) * ev.displacement(bb, q);
          for (int i = 0; i < d; ++i)
            K[static_cast<std::size_t>(S.displacementOffset(i) + a) * L + S.displacementOffset(i) +
              bb] += v;
        }
      for (int a = 0; a < nCP; ++a)
        for (int bb = 0; bb < nCP; ++bb) {
          const double v = w * ev.rotation(a, q) * ev.rotation(bb, q);
          for (int c = 0; c < r; ++c)
            K[static_cast<std::size_t>(S.rotationOffset(c) + a) * L + S.rotationOffset(c) + bb] +=
                v;
        }
    }
    const LO* cols = &impl_->elementColumns[ek * static_cast<std::size_t>(L)];
    for (int i = 0; i < L; ++i)
      if (cols[i] < impl_->numOwned)
        M->sumIntoLocalValues(cols[i], L, &K[static_cast<std::size_t>(i) * L], cols, false);
  }
  M->fillComplete(impl_->owned, impl_->owned);
  impl_->fieldMass = M;
  return M;
}

Teuchos::RCP<const CrsMatrix> MixedElasticityAssembler::matrix() const { return impl_->matrix; }
Teuchos::RCP<const MultiVector> MixedElasticityAssembler::rhs() const { return impl_->rhs; }
Teuchos::RCP<const Map> MixedElasticityAssembler::ownedMap() const { return impl_->owned; }
Teuchos::RCP<const Map> MixedElasticityAssembler::overlapMap() const { return impl_->overlap; }

Teuchos::RCP<const MultiVector> MixedElasticityAssembler::physicalScaling(double twoMu) const
{
  auto D = Teuchos::rcp(new MultiVector(impl_->owned, 1));
  auto data = D->getDataNonConst(0);
  const double s = std::sqrt(twoMu);
  for (long i = 0; i < static_cast<long>(data.size()); ++i)
    data[i] = impl_->owned->getGlobalElement(i) < space_->numStressDofs() ? s : 1.0 / s;
  return D;
}

Teuchos::RCP<MultiVector> MixedElasticityAssembler::createVector() const
{
  return Teuchos::rcp(new MultiVector(impl_->owned, 1));
}

Teuchos::RCP<MultiVector> MixedElasticityAssembler::toOverlap(const MultiVector& owned) const
{
  auto v = Teuchos::rcp(new MultiVector(impl_->overlap, owned.getNumVectors()));
  v->doImport(owned, *impl_->importer, Tpetra::INSERT);
  return v;
}

}  // namespace sc::assembly
