#include "engine/bond_colouring.hpp"

#include <algorithm>
#include <stdexcept>

#include "engine/bytes.hpp"
#include "engine/context.hpp"

namespace pdq {

namespace {

// The greedy colouring of the graph whose vertex k (global IDs sorted) has the partners
// adj[start[k] .. start[k+1]) (vertex numbers): each vertex in turn takes the lowest colour
// that no vertex within two bonds of it has taken.
std::vector<long> greedy(const std::vector<std::size_t>& start, const std::vector<std::size_t>& adj,
                         long& count) {
  const std::size_t n = start.size() - 1;
  std::vector<long> colour(n, -1);
  std::vector<std::size_t> seen;  // per colour: the last vertex that found it taken
  count = 0;
  for (std::size_t v = 0; v < n; ++v) {
    auto mark = [&](std::size_t u) {
      if (colour[u] >= 0) seen[static_cast<std::size_t>(colour[u])] = v + 1;
    };
    for (std::size_t a = start[v]; a < start[v + 1]; ++a) {
      const std::size_t u = adj[a];
      mark(u);
      for (std::size_t b = start[u]; b < start[u + 1]; ++b) mark(adj[b]);
    }
    long c = 0;
    while (c < count && seen[static_cast<std::size_t>(c)] == v + 1) ++c;
    if (c == count) seen.push_back(0), ++count;
    colour[v] = c;
  }
  return colour;
}

}  // namespace

std::vector<long> bondColours(Context& ctx, long& count) {
  const Particles& P = ctx.particles;
  const Bonds& B = ctx.bonds;
  const std::size_t n = P.owned();
  // Per owned particle: its global ID, its bond count and its partners' IDs.
  std::vector<char> mine;
  for (std::size_t i = 0; i < n; ++i) {
    const Gid g = P.gid(i);
    const unsigned long m = B.end(i) - B.begin(i);
    bytes::append(mine, &g, 1);
    bytes::append(mine, &m, 1);
    if (m > 0) bytes::append(mine, B.partnerGids(B.begin(i)), m);
  }
  std::vector<std::size_t> starts;
  const std::vector<char> all = ctx.gather(mine, starts);
  std::vector<char> reply;  // rank 0: the colour count, the sorted IDs and their colours
  if (ctx.root()) {
    std::vector<std::pair<Gid, const char*>> rows;  // each particle's ID and partners
    for (const char* in = all.data(); in < all.data() + all.size();) {
      Gid g = 0;
      unsigned long m = 0;
      bytes::take(in, &g, 1);
      rows.push_back({g, in});
      bytes::take(in, &m, 1);
      in += m * sizeof(Gid);
    }
    std::sort(rows.begin(), rows.end());
    std::vector<Gid> ids(rows.size());
    for (std::size_t k = 0; k < rows.size(); ++k) ids[k] = rows[k].first;
    // The edges both ways (a model may keep a bond on one side only), once each.
    std::vector<std::pair<std::size_t, std::size_t>> edges;
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const char* in = rows[k].second;
      unsigned long m = 0;
      bytes::take(in, &m, 1);
      std::vector<Gid> partners(m);
      bytes::take(in, partners.data(), m);
      for (Gid p : partners) {
        const auto it = std::lower_bound(ids.begin(), ids.end(), p);
        if (it == ids.end() || *it != p)
          throw std::logic_error("bond colouring: a bond's partner is no particle");
        const auto j = static_cast<std::size_t>(it - ids.begin());
        edges.push_back({k, j});
        edges.push_back({j, k});
      }
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    std::vector<std::size_t> start(ids.size() + 1, 0), adj(edges.size());
    for (std::size_t e = 0; e < edges.size(); ++e) {
      ++start[edges[e].first + 1];
      adj[e] = edges[e].second;
    }
    for (std::size_t k = 0; k < ids.size(); ++k) start[k + 1] += start[k];
    const std::vector<long> colour = greedy(start, adj, count);
    const unsigned long total = ids.size();
    bytes::append(reply, &count, 1);
    bytes::append(reply, &total, 1);
    bytes::append(reply, ids.data(), ids.size());
    bytes::append(reply, colour.data(), colour.size());
  }
  reply = ctx.broadcast(std::move(reply));
  const char* in = reply.data();
  unsigned long total = 0;
  bytes::take(in, &count, 1);
  bytes::take(in, &total, 1);
  std::vector<Gid> ids(total);
  std::vector<long> colour(total);
  bytes::take(in, ids.data(), total);
  bytes::take(in, colour.data(), total);
  std::vector<long> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto it = std::lower_bound(ids.begin(), ids.end(), P.gid(i));
    out[i] = colour[static_cast<std::size_t>(it - ids.begin())];
  }
  return out;
}

}  // namespace pdq
