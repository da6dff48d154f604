// Nested dissection of the nonzero-diagonal graph with the zero-diagonal rows placed after their
// neighbours (see the header).

#include <sc/solvers/SaddlePointOrdering.hpp>

#include <algorithm>
#include <chrono>
#include <climits>

#include <metis.h>

#include <sc/core/Error.hpp>

namespace sc::solvers {

namespace {

// Removes the duplicates from each row of a CSR adjacency (order kept), compacting in place:
// one pass with a marker per column, O(entries).
void removeDuplicates(std::vector<std::int64_t>& start, std::vector<int>& adj, int columns)
{
  const size_t rows = start.size() - 1;
  std::vector<std::int64_t> seen(static_cast<size_t>(columns), -1);
  std::int64_t out = 0;
  for (size_t r = 0; r < rows; ++r) {
    const auto b = start[r], e = start[r + 1];
    start[r] = out;
    for (auto k = b; k < e; ++k) {
      const int c = adj[static_cast<size_t>(k)];
      if (seen[static_cast<size_t>(c)] == static_cast<std::int64_t>(r)) continue;
      seen[static_cast<size_t>(c)] = static_cast<std::int64_t>(r);
      adj[static_cast<size_t>(out++)] = c;
    }
  }
  start[rows] = out;
  adj.resize(static_cast<size_t>(out));
}

}  // namespace

std::vector<int> saddlePointOrdering(int n, const std::vector<std::int64_t>& rowStart,
                                     const std::vector<int>& columns,
                                     const std::vector<char>& zeroDiagonal, double* metisSeconds)
{
  SC_THROW_IF(n < 0 || rowStart.size() != static_cast<size_t>(n) + 1 ||
                  zeroDiagonal.size() != static_cast<size_t>(n) ||
                  rowStart.back() != static_cast<std::int64_t>(columns.size()),
              sc::core::InternalError, "saddlePointOrdering: inconsistent graph arrays");
  // Compact numbering of the rows with a nonzero diagonal (the vertices METIS orders).
  std::vector<int> vertex(static_cast<size_t>(n), -1);
  std::vector<int> row;  // vertex -> row
  for (int i = 0; i < n; ++i)
    if (!zeroDiagonal[static_cast<size_t>(i)]) {
      vertex[static_cast<size_t>(i)] = static_cast<int>(row.size());
      row.push_back(i);
    }
  const int m = static_cast<int>(row.size());

  // Nonzero-diagonal neighbours of every zero-diagonal row, in A and in Aᵀ.
  std::vector<std::int64_t> zStart(static_cast<size_t>(n) + 1, 0);
  for (int i = 0; i < n; ++i)
    for (auto k = rowStart[static_cast<size_t>(i)]; k < rowStart[static_cast<size_t>(i) + 1]; ++k) {
      const int j = columns[static_cast<size_t>(k)];
      SC_THROW_IF(j < 0 || j >= n, sc::core::InternalError,
                  "saddlePointOrdering: column " << j << " outside 0.." << n - 1);
      if (zeroDiagonal[static_cast<size_t>(i)] && vertex[static_cast<size_t>(j)] >= 0)
        ++zStart[static_cast<size_t>(i) + 1];
      if (zeroDiagonal[static_cast<size_t>(j)] && vertex[static_cast<size_t>(i)] >= 0)
        ++zStart[static_cast<size_t>(j) + 1];
    }
  for (int i = 0; i < n; ++i)
    zStart[static_cast<size_t>(i) + 1] += zStart[static_cast<size_t>(i)];
  std::vector<int> zAdj(static_cast<size_t>(zStart[static_cast<size_t>(n)]));
  {
    std::vector<std::int64_t> fill(zStart.begin(), zStart.end() - 1);
    for (int i = 0; i < n; ++i)
      for (auto k = rowStart[static_cast<size_t>(i)]; k < rowStart[static_cast<size_t>(i) + 1];
           ++k) {
        const int j = columns[static_cast<size_t>(k)];
        if (zeroDiagonal[static_cast<size_t>(i)] && vertex[static_cast<size_t>(j)] >= 0)
          zAdj[static_cast<size_t>(fill[static_cast<size_t>(i)]++)] =
              vertex[static_cast<size_t>(j)];
        if (zeroDiagonal[static_cast<size_t>(j)] && vertex[static_cast<size_t>(i)] >= 0)
          zAdj[static_cast<size_t>(fill[static_cast<size_t>(j)]++)] =
              vertex[static_cast<size_t>(i)];
      }
  }
  removeDuplicates(zStart, zAdj, m);

  // Each zero-diagonal row is glued to one nonzero-diagonal neighbour, its host: the neighbour
  // with the fewest rows glued to it so far, then the shortest row (an element's interior stress
  // unknowns before those it shares), then the lowest index. A host and its rows are one vertex
  // of the graph METIS orders (weight: the number of rows), and the rows follow their host in the
  // pivot order: the host's 2 × 2 block [[a, b], [b, 0]] is a stable pivot.
  std::vector<int> host(static_cast<size_t>(n), -1), glued(static_cast<size_t>(m), 0);
  for (int i = 0; i < n; ++i) {
    if (!zeroDiagonal[static_cast<size_t>(i)]) continue;
    int best = -1;
    for (auto k = zStart[static_cast<size_t>(i)]; k < zStart[static_cast<size_t>(i) + 1]; ++k) {
      const int v = zAdj[static_cast<size_t>(k)];
      if (best < 0) {
        best = v;
        continue;
      }
      const auto length = [&](int w) {
        const int r = row[static_cast<size_t>(w)];
        return rowStart[static_cast<size_t>(r) + 1] - rowStart[static_cast<size_t>(r)];
      };
      const auto gv = glued[static_cast<size_t>(v)], gb = glued[static_cast<size_t>(best)];
      if (gv < gb || (gv == gb && length(v) < length(best))) best = v;
    }
    host[static_cast<size_t>(i)] = best;
    if (best >= 0) ++glued[static_cast<size_t>(best)];
  }
  const auto vertexOf = [&](int i) {
    return zeroDiagonal[static_cast<size_t>(i)] ? host[static_cast<size_t>(i)]
                                                : vertex[static_cast<size_t>(i)];
  };

  // The graph METIS orders: A + Aᵀ with every zero-diagonal row merged into its host.
  std::vector<std::int64_t> start(static_cast<size_t>(m) + 1, 0);
  auto addEdges = [&](auto&& edge) {
    for (int i = 0; i < n; ++i) {
      const int vi = vertexOf(i);
      if (vi < 0) continue;
      for (auto k = rowStart[static_cast<size_t>(i)]; k < rowStart[static_cast<size_t>(i) + 1];
           ++k) {
        const int vj = vertexOf(columns[static_cast<size_t>(k)]);
        if (vj >= 0 && vj != vi) edge(vi, vj);
      }
    }
  };
  addEdges([&](int a, int b) {
    ++start[static_cast<size_t>(a) + 1];
    ++start[static_cast<size_t>(b) + 1];
  });
  for (int v = 0; v < m; ++v)
    start[static_cast<size_t>(v) + 1] += start[static_cast<size_t>(v)];
  SC_THROW_IF(start[static_cast<size_t>(m)] > INT_MAX, sc::core::Error,
              "METIS ordering: the graph has " << start[static_cast<size_t>(m)]
                                               << " directed edges, more than METIS' 32-bit "
                                                  "indices allow; use another MUMPS/Ordering");
  std::vector<int> adj(static_cast<size_t>(start[static_cast<size_t>(m)]));
  {
    std::vector<std::int64_t> fill(start.begin(), start.end() - 1);
    addEdges([&](int a, int b) {
      adj[static_cast<size_t>(fill[static_cast<size_t>(a)]++)] = b;
      adj[static_cast<size_t>(fill[static_cast<size_t>(b)]++)] = a;
    });
  }
  removeDuplicates(start, adj, m);

  // METIS' order of the vertices (perm[p] = the vertex at place p).
  std::vector<idx_t> perm(static_cast<size_t>(m)), iperm(static_cast<size_t>(m));
  if (m > 0 && !adj.empty()) {
    std::vector<idx_t> xadj(start.begin(), start.end());
    std::vector<idx_t> weight(static_cast<size_t>(m));
    for (int v = 0; v < m; ++v)
      weight[static_cast<size_t>(v)] = 1 + glued[static_cast<size_t>(v)];
    idx_t nv = m;
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_NUMBERING] = 0;
    const auto t0 = std::chrono::steady_clock::now();
    const int status = METIS_NodeND(&nv, xadj.data(), adj.data(), weight.data(), options,
                                    perm.data(), iperm.data());
    if (metisSeconds)
      *metisSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    SC_THROW_IF(status != METIS_OK, sc::core::Error,
                "METIS_NodeND failed (status " << status << ") on a graph of " << m << " vertices");
  } else {
    for (int v = 0; v < m; ++v)
      perm[static_cast<size_t>(v)] = iperm[static_cast<size_t>(v)] = v;
  }

  // The rows glued to each host (in index order), and the zero-diagonal rows without a
  // nonzero-diagonal neighbour (bucket m: placed last).
  std::vector<int> bucketStart(static_cast<size_t>(m) + 2, 0);
  for (int i = 0; i < n; ++i)
    if (zeroDiagonal[static_cast<size_t>(i)]) {
      const int h = host[static_cast<size_t>(i)];
      ++bucketStart[static_cast<size_t>(h < 0 ? m : h) + 1];
    }
  for (int p = 0; p <= m; ++p)
    bucketStart[static_cast<size_t>(p) + 1] += bucketStart[static_cast<size_t>(p)];
  std::vector<int> bucket(static_cast<size_t>(bucketStart[static_cast<size_t>(m) + 1]));
  {
    std::vector<int> fill(bucketStart.begin(), bucketStart.end() - 1);
    for (int i = 0; i < n; ++i)
      if (zeroDiagonal[static_cast<size_t>(i)]) {
        const int h = host[static_cast<size_t>(i)];
        bucket[static_cast<size_t>(fill[static_cast<size_t>(h < 0 ? m : h)]++)] = i;
      }
  }
  std::vector<int> position(static_cast<size_t>(n), -1);
  int next = 0;
  for (int p = 0; p <= m; ++p) {
    const int v = p < m ? static_cast<int>(perm[static_cast<size_t>(p)]) : m;
    if (p < m) position[static_cast<size_t>(row[static_cast<size_t>(v)])] = next++;
    for (int b = bucketStart[static_cast<size_t>(v)]; b < bucketStart[static_cast<size_t>(v) + 1];
         ++b)
      position[static_cast<size_t>(bucket[static_cast<size_t>(b)])] = next++;
  }
  SC_THROW_IF(next != n, sc::core::InternalError,
              "saddlePointOrdering: placed " << next << " of " << n << " unknowns");
  return position;
}

}  // namespace sc::solvers
