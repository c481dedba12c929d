// SPDX-License-Identifier: GPL-3.0-or-later
// The adversarial order class of adversarial_search.h on starts too large for
// it (more than 9 points), under every reading. The question is the same:
// every state (cells and tags) at a cycle's end that some sequence of orders
// reaches, and from each whether a cycle can end the run. Settled, it decides
// the uniformly random class too: a uniform random order gives every order a
// positive chance each cycle, so random orders end the run with probability
// one exactly when an end stays reachable from every state reached.
//
// What makes larger starts searchable: the search branches only on the visits
// that change the state (a swap or a new tag). A visit that changes nothing
// (an inert visit: the facet is passed over, or its decision neither swaps nor
// tags) or the pass of a listed facet that is not there leaves the state as it
// is; it only uses up that facet's turn. So an order of a cycle is its
// sequence of changing visits e1 ... ek, each of a listed facet not visited
// before, plus for every other listed facet a moment (before e1, between two,
// or after ek) at which it is not there or its visit is inert. Conversely any
// such sequence is an order: put each other facet at such a moment. A node of
// a cycle's search is (cells, tags, the listed facets not visited yet, those
// of them that have had no such moment yet, busy); the cycle may end at a node
// where the last set is empty. With same-cycle readings the listed facets are
// every vertex triple (the adversary's sweep gives each one turn): a triple
// not there at the cycle's start has had its moment, and a facet made in the
// cycle may be visited in it, once. The ends, and the fewest swaps of each,
// are the same as when every order of the listed facets is tried, as
// adversarial_search.h does; the test "Adversarial orders: the effective-visit
// search reaches the same states, loops and answers as the adversarial search"
// compares them start by start on 6 points (every reading) and 7.
//
// With `reduce`, the partial-order reduction of adversarial_search.h: after a
// changing visit h from node n, a facet g listed before h is not visited next
// when g then h and h then g, from n, both change the state at each step and
// end in the same node with the same swaps. Two visits whose five points share
// at most two points commute unless an owed facet has two of its points in
// both (neither reads a cell the other writes); other pairs are tried.
//
// Cells and facets are numbered as they are met, in sets of W 64-bit words
// (W = 4, 16, 64); a set of starts that meets more than 64 W of either is
// searched again with the next W.
// The rule is the checker's model (`Checker::decide` and `apply`): each
// decision is computed on the whole state once and kept by what it depends
// on (the facet, its two apexes, which cells of the five points are there and
// tagged), except the planar configurations (2-2 and 4-4), which look beyond
// the five points and are computed anew each time.

#ifndef EDGE_SWAPPING_3_LABORATORY_EFFECTIVE_VISIT_SEARCH_H
#define EDGE_SWAPPING_3_LABORATORY_EFFECTIVE_VISIT_SEARCH_H

#include "adversarial_search.h"
#include <deque>
#include <functional>

namespace effective_visit_search {

using adversarial_search::Loop_found;
using adversarial_search::Search_limit_reached;
using trace_checker::Cell;
using trace_checker::Checker;
using trace_checker::Facet;

/// More cells or facets met than a set of W words holds.
struct Too_many_numbers
{
};

template <int W>
struct Bits
{
  std::array<std::uint64_t, W> w{};

  void set(int k) { w[std::size_t(k >> 6)] |= std::uint64_t(1) << (k & 63); }
  void reset(int k) { w[std::size_t(k >> 6)] &= ~(std::uint64_t(1) << (k & 63)); }
  bool test(int k) const { return (w[std::size_t(k >> 6)] >> (k & 63)) & 1; }
  bool empty() const
  {
    for(std::uint64_t x : w)
      if(x != 0) return false;
    return true;
  }
  Bits minus(const Bits& o) const
  {
    Bits r;
    for(int i = 0; i < W; ++i) r.w[std::size_t(i)] = w[std::size_t(i)] & ~o.w[std::size_t(i)];
    return r;
  }
  Bits intersection(const Bits& o) const
  {
    Bits r;
    for(int i = 0; i < W; ++i) r.w[std::size_t(i)] = w[std::size_t(i)] & o.w[std::size_t(i)];
    return r;
  }
  bool operator==(const Bits& o) const { return w == o.w; }
  bool operator<(const Bits& o) const { return w < o.w; }
  std::uint64_t hash() const
  {
    std::uint64_t h = 0x632BE59BD9B4E019ull;
    for(std::uint64_t x : w) h = (h ^ x) * 0x9E3779B97F4A7C15ull + (h >> 29);
    return h;
  }
  template <class F>
  void for_each(F f) const
  {
    for(int i = 0; i < W; ++i)
      for(std::uint64_t b = w[std::size_t(i)]; b != 0; b &= b - 1) f(64 * i + __builtin_ctzll(b));
  }
};

/// The cells and facets met so far, numbered, and the visits decided so far.
template <int W>
class Space
{
public:
  typedef Bits<W> Set;

  explicit Space(const nlohmann::json& header) : model_(header)
  {
    std::string reading = header.at("reading").get<std::string>();
    clear_tags_each_cycle_ = reading.rfind("cleared-each-cycle", 0) == 0;
    tags_outlive_cells_ = reading.rfind("never-cleared", 0) == 0;
    if(model_.points().size() > 4096) throw std::invalid_argument("effective-visit search: at most 4096 points");
    // Same-cycle: a sweep gives every vertex triple a turn, so every triple is numbered now.
    if(model_.visits_made_facets())
    {
      const std::size_t n = model_.points().size();
      for(std::size_t i = 0; i < n; ++i)
        for(std::size_t j = i + 1; j < n; ++j)
          for(std::size_t k = j + 1; k < n; ++k) all_triples_.set(facet_number(Facet{i, j, k}));
    }
  }

  int cell_number(const Cell& t)
  {
    const auto [it, added] = cell_number_.emplace(pack(t), int(cells_.size()));
    if(added)
    {
      if(cells_.size() >= std::size_t(64 * W)) throw Too_many_numbers();
      cells_.push_back(t);
      std::array<int, 4> facets;
      for(int skip = 0; skip < 4; ++skip)
      {
        Facet f;
        int m = 0;
        for(int k = 0; k < 4; ++k)
          if(k != skip) f[std::size_t(m++)] = t[std::size_t(k)];
        const int n = facet_number(f);
        facets[std::size_t(skip)] = n;
        facet_cells_[std::size_t(n)].push_back(it->second);
      }
      cell_facets_.push_back(facets);
    }
    return it->second;
  }
  int facet_number(const Facet& f)
  {
    const auto [it, added] = facet_number_.emplace(f, int(facets_.size()));
    if(added)
    {
      if(facets_.size() >= std::size_t(64 * W)) throw Too_many_numbers();
      facets_.push_back(f);
      facet_cells_.emplace_back();
      facet_fives_.emplace_back();
      facet_points_.push_back(point_bit(f[0]) | point_bit(f[1]) | point_bit(f[2]));
    }
    return it->second;
  }
  const Facet& facet(int k) const { return facets_[std::size_t(k)]; }

  Set cell_set(const std::set<Cell>& cells)
  {
    Set s;
    for(const Cell& t : cells) s.set(cell_number(t));
    return s;
  }
  std::set<Cell> cells_of(const Set& s) const
  {
    std::set<Cell> out;
    s.for_each([&](int k) { out.insert(cells_[std::size_t(k)]); });
    return out;
  }

  /// The interior facets of the cells: those in two of them.
  Set interior(const Set& cells) const { return adversarial_search::interior_facets(cells, cell_facets_); }
  /// The facets a cycle from `cells` lists: those there at its start
  /// (next-cycle), or every vertex triple (same-cycle: the adversary's sweep).
  Set listed(const Set& cells) const { return model_.visits_made_facets() ? all_triples_ : interior(cells); }

  /// The tags at a cycle's start, as the reading says.
  Set round_start_tags(const Set& tags) const { return clear_tags_each_cycle_ ? Set() : tags; }

  bool is_delaunay(const Set& cells)
  {
    model_.set_state(cells_of(cells), {});
    return model_.is_delaunay();
  }

  struct Visit
  {
    Set cells, tags;
    bool swap = false, changed = false;
    // The points of the cells the visit reads and writes: a facet with fewer
    // than two of its points among them reads nothing the visit changes.
    std::uint64_t footprint = 0;
  };

  /// One visit of facet number `f`: nothing if the facet is not there.
  Visit visit(const Set& cells, const Set& tags, int f)
  {
    Visit v{cells, tags};
    const Local* r = decision(cells, tags, f, v.footprint);
    return r ? apply(v, *r) : v;
  }

  /// Whether visiting facet number `f` changes the state (not there: no).
  bool changes(const Set& cells, const Set& tags, int f)
  {
    std::uint64_t footprint;
    const Local* r = decision(cells, tags, f, footprint);
    return r && (r->swap || !r->new_tags.empty());
  }

  /// The points of facet number `f`, as bits (all bits with more than 64 points).
  std::uint64_t facet_points(int f) const { return facet_points_[std::size_t(f)]; }
  /// Whether the facets a visit may change are known from its footprint:
  /// not once a planar configuration, which looks beyond its five points, is met.
  bool footprints_hold() const { return !planar_met_; }

private:
  struct Local
  {
    bool swap = false, local = true;
    std::vector<int> old_cells, new_cells, new_tags;
  };

  // The decision of a visit of facet number `f`, and its footprint; null if
  // the facet is not there. A planar decision is valid until the next call.
  const Local* decision(const Set& cells, const Set& tags, int f, std::uint64_t& footprint)
  {
    int holders[2], found = 0;
    for(int t : facet_cells_[std::size_t(f)])
      if(cells.test(t))
      {
        if(found == 2) throw std::logic_error("a facet in three cells");
        holders[found++] = t;
      }
    if(found < 2) return nullptr;
    const Facet& facet = facets_[std::size_t(f)];
    Five& five = five_of(holders[0], holders[1], f);
    const std::size_t d = five.d, e = five.e;
    // The five points' cells: which are there and tagged.
    if(five.cells_met != cells_.size()) // cells met since: look again for those not met
    {
      for(int skip = 0; skip < 5; ++skip)
        if(five.cells[std::size_t(skip)] < 0) five.cells[std::size_t(skip)] = find_cell(five.points, skip);
      five.cells_met = cells_.size();
    }
    std::uint64_t there = 0, tagged = 0;
    for(int skip = 0; skip < 5; ++skip)
    {
      const int t = five.cells[std::size_t(skip)];
      if(t >= 0 && cells.test(t))
      {
        there |= std::uint64_t(1) << skip;
        if(tags.test(t)) tagged |= std::uint64_t(1) << skip;
      }
    }
    const std::uint16_t key = std::uint16_t((there << 5) | tagged);
    footprint = point_bit(facet[0]) | point_bit(facet[1]) | point_bit(facet[2]) | point_bit(d) | point_bit(e);
    for(const auto& [k, local] : five.decided)
      if(k == key) return &decisions_[local];
    Local local = decide(cells, tags, facet, d, e);
    if(!local.local)
    {
      planar_met_ = true; // looks beyond the five points: not kept
      footprint |= points_of(local.old_cells) | points_of(local.new_cells);
      planar_ = std::move(local);
      return &planar_;
    }
    five.decided.emplace_back(key, decisions_.size());
    decisions_.push_back(std::move(local));
    return &decisions_.back();
  }

  static std::uint64_t pack(const Cell& t)
  {
    return std::uint64_t(t[0]) | (std::uint64_t(t[1]) << 16) | (std::uint64_t(t[2]) << 32) | (std::uint64_t(t[3]) << 48);
  }
  std::uint64_t points_of(const std::vector<int>& cells) const
  {
    std::uint64_t m = 0;
    for(int t : cells)
      for(std::size_t v : cells_[std::size_t(t)]) m |= point_bit(v);
    return m;
  }
  std::uint64_t point_bit(std::size_t v) const
  {
    return model_.points().size() > 64 ? ~std::uint64_t(0) : std::uint64_t(1) << v;
  }

  // The five points of a facet and the apexes of its two cells (the facet's
  // points, then d, e as the checker orders them), and the number of the cell
  // without each of them, -1 while not met: a visit then looks up no cell.
  struct Five
  {
    std::size_t d, e;
    std::array<std::size_t, 5> points;
    std::array<int, 5> cells;
    std::size_t cells_met; // how many cells were met when `cells` was looked up
    // The decisions made, by which of the cells are there and tagged (bits by
    // point left out): the facet and its apexes are the five's.
    std::vector<std::pair<std::uint16_t, std::size_t>> decided;
  };
  // The five of facet number `f` between cells c and c2.
  Five& five_of(int c, int c2, int f)
  {
    const std::uint64_t key = (std::uint64_t(std::min(c, c2)) << 32) | std::uint64_t(std::max(c, c2));
    for(const auto& [k, five] : facet_fives_[std::size_t(f)])
      if(k == key) return fives_[five];
    const Facet& facet = facets_[std::size_t(f)];
    Five five;
    five.d = apex(c, facet);
    five.e = apex(c2, facet);
    if(CGAL::compare_xyz(model_.points()[five.e], model_.points()[five.d]) == CGAL::SMALLER) std::swap(five.d, five.e);
    five.points = {facet[0], facet[1], facet[2], five.d, five.e};
    for(int skip = 0; skip < 5; ++skip) five.cells[std::size_t(skip)] = find_cell(five.points, skip);
    five.cells_met = cells_.size();
    facet_fives_[std::size_t(f)].emplace_back(key, fives_.size());
    fives_.push_back(std::move(five));
    return fives_.back();
  }
  // The number of the cell of `five` without point number `skip`, or -1.
  int find_cell(const std::array<std::size_t, 5>& five, int skip) const
  {
    Cell t;
    int m = 0;
    for(int k = 0; k < 5; ++k)
      if(k != skip) t[std::size_t(m++)] = five[std::size_t(k)];
    std::sort(t.begin(), t.end());
    const auto it = cell_number_.find(pack(t));
    return it == cell_number_.end() ? -1 : it->second;
  }

  std::size_t apex(int cell, const Facet& f) const
  {
    for(std::size_t v : cells_[std::size_t(cell)])
      if(v != f[0] && v != f[1] && v != f[2]) return v;
    throw std::logic_error("no apex");
  }

  // The checker's decision, on the whole state, and its flip carried out by
  // the checker too (which checks it keeps the volume and makes no flat cell).
  Local decide(const Set& cells, const Set& tags, const Facet& f, std::size_t d, std::size_t e)
  {
    model_.set_state(cells_of(cells), cells_of(tags));
    const auto apexes = model_.apexes(f);
    if(apexes.first != d || apexes.second != e) throw std::logic_error("apexes differ from the checker's");
    const Checker::Decision r = model_.decide(f, d, e);
    model_.apply(r);
    Local local;
    local.swap = r.swap;
    local.local = r.kind.rfind("planar", 0) != 0;
    for(const Cell& t : r.old_cells) local.old_cells.push_back(cell_number(t));
    for(const Cell& t : r.new_cells) local.new_cells.push_back(cell_number(t));
    for(const Cell& t : r.new_tags) local.new_tags.push_back(cell_number(t));
    // The sets' arithmetic below must give the checker's state.
    Visit check{cells, tags};
    check = apply(check, local);
    if(cells_of(check.cells) != model_.cells() || cells_of(check.tags) != model_.tags())
      throw std::logic_error("the visit's state differs from the checker's");
    return local;
  }

  Visit apply(Visit v, const Local& r) const
  {
    for(int t : r.new_tags) v.tags.set(t);
    if(r.swap)
    {
      for(int t : r.old_cells)
      {
        v.cells.reset(t);
        if(!tags_outlive_cells_) v.tags.reset(t);
      }
      for(int t : r.new_cells) v.cells.set(t);
    }
    v.swap = r.swap;
    v.changed = r.swap || (!r.new_tags.empty() && !model_.ends_without_swap());
    return v;
  }

  Checker model_;
  bool clear_tags_each_cycle_ = false, tags_outlive_cells_ = false;
  std::vector<Cell> cells_;
  std::vector<Facet> facets_;
  std::vector<std::array<int, 4>> cell_facets_; // by cell number
  std::vector<std::vector<int>> facet_cells_;   // by facet number: the cells met that hold it
  std::vector<std::uint64_t> facet_points_;     // by facet number
  bool planar_met_ = false;
  Set all_triples_; // same-cycle only
  std::unordered_map<std::uint64_t, int> cell_number_; // by pack()
  std::map<Facet, int> facet_number_;
  std::deque<Local> decisions_; // kept in place: visits hold them
  Local planar_; // the last planar decision
  std::deque<Five> fives_;
  std::vector<std::vector<std::pair<std::uint64_t, std::size_t>>> facet_fives_; // by facet: its two cells -> its five
};

// Every end of one cycle from a state at its start: the state, whether the
// cycle was busy, its fewest swaps and one sequence of changing visits that
// reaches it with them. The memo and the reduction are those of
// adversarial_search::Cycle_search, on the nodes described above.
template <int W>
struct Cycle_search
{
  typedef Bits<W> Set;
  Space<W>& space;
  std::size_t max_nodes;
  bool reduce = false;
  std::size_t nodes = 0;
  struct Node
  {
    Set cells, tags, left, owed; // left: not visited yet; owed: of those, no inert moment yet
    bool busy;
    bool operator==(const Node& o) const
    {
      return busy == o.busy && cells == o.cells && tags == o.tags && left == o.left && owed == o.owed;
    }
  };
  struct Node_hash
  {
    std::size_t operator()(const Node& n) const
    {
      return std::size_t(n.cells.hash() ^ (n.tags.hash() * 31) ^ (n.left.hash() * 961) ^ (n.owed.hash() * 29791) ^
                         std::uint64_t(n.busy));
    }
  };
  struct Searched
  {
    std::size_t swaps;
    Set not_searched;
  };
  std::unordered_map<Node, Searched, Node_hash> seen;
  std::map<std::tuple<Set, Set, bool>, std::pair<std::size_t, std::vector<int>>> ends;
  bool can_end = false, can_end_off_delaunay = false;

  /// The facets of `among` whose visit changes the state (not there: no).
  Set changing(const Set& cells, const Set& tags, const Set& among)
  {
    Set out;
    among.for_each([&](int f) {
      if(space.changes(cells, tags, f)) out.set(f);
    });
    return out;
  }

  // A node's sets of facets after a changing visit: `active` holds the facets
  // of `left` whose visit changes the state. Only facets with two points or
  // more in the visit's footprint can change from changing to inert or back.
  struct Step
  {
    typename Space<W>::Visit visit;
    Set left, owed, active;
  };
  Step step(const Set& cells, const Set& tags, const Set& left, const Set& owed, const Set& active, int f)
  {
    Step s{space.visit(cells, tags, f), left, owed, active};
    s.left.reset(f);
    s.owed.reset(f);
    s.active.reset(f);
    const bool filter = space.footprints_hold();
    s.left.for_each([&](int g) {
      if(filter && __builtin_popcountll(space.facet_points(g) & s.visit.footprint) < 2) return;
      if(space.changes(s.visit.cells, s.visit.tags, g)) s.active.set(g);
      else s.active.reset(g);
    });
    s.owed = s.owed.intersection(s.active); // not there or inert now: its moment
    return s;
  }

  /// Whether changing visits g and f, from a node, commute: the same node
  /// after both in either order, with the same swaps and activity.
  bool commute(const Set& cells, const Set& tags, const Set& left, const Set& owed, const Set& active, int g, int f)
  {
    if(space.footprints_hold())
    {
      // Footprints sharing at most two points: neither reads what the other
      // writes; the node is the same unless a facet owed reads both.
      const std::uint64_t pf = space.visit(cells, tags, f).footprint, pg = space.visit(cells, tags, g).footprint;
      if(__builtin_popcountll(pf & pg) <= 2)
      {
        bool both = false;
        owed.for_each([&](int h) {
          const std::uint64_t ph = space.facet_points(h);
          both = both || (__builtin_popcountll(ph & pf) >= 2 && __builtin_popcountll(ph & pg) >= 2);
        });
        if(!both) return true;
      }
    }
    const Step a1 = step(cells, tags, left, owed, active, g);
    if(!a1.active.test(f)) return false;
    const Step a2 = step(a1.visit.cells, a1.visit.tags, a1.left, a1.owed, a1.active, f);
    const Step b1 = step(cells, tags, left, owed, active, f);
    if(!b1.active.test(g)) return false;
    const Step b2 = step(b1.visit.cells, b1.visit.tags, b1.left, b1.owed, b1.active, g);
    return int(a1.visit.swap) + int(a2.visit.swap) == int(b1.visit.swap) + int(b2.visit.swap) &&
           (a1.visit.changed || a2.visit.changed) == (b1.visit.changed || b2.visit.changed) &&
           a2.visit.cells == b2.visit.cells && a2.visit.tags == b2.visit.tags && a2.owed == b2.owed;
  }

  /// The search from a cycle's start.
  void run(const Set& cells, const Set& tags, const Set& listed)
  {
    const Set active = changing(cells, tags, listed);
    std::vector<int> order;
    run(cells, tags, listed, active, active, false, 0, order, Set());
  }

  void run(const Set& cells, const Set& tags, const Set& left, const Set& owed, const Set& active, bool busy,
           std::size_t swaps, std::vector<int>& order, const Set& not_next)
  {
    Set next = active.minus(not_next);
    const auto [it, added] = seen.try_emplace(Node{cells, tags, left, owed, busy}, Searched{swaps, not_next});
    bool record = added;
    if(!added)
    {
      Searched& before = it->second;
      if(swaps < before.swaps)
      {
        before.swaps = swaps;
        record = true;
      }
      else
      {
        next = before.not_searched.minus(not_next).intersection(active);
        if(next.empty()) return;
      }
      before.not_searched = before.not_searched.intersection(not_next);
    }
    if(++nodes > max_nodes) throw Search_limit_reached();
    if(record && owed.empty()) adversarial_search::record_end(*this, cells, tags, busy, swaps, order);
    next.for_each([&](int f) {
      Set after_f;
      if(reduce)
        active.for_each([&](int g) {
          if(g < f && commute(cells, tags, left, owed, active, g, f)) after_f.set(g);
        });
      const Step s = step(cells, tags, left, owed, active, f);
      order.push_back(f);
      run(s.visit.cells, s.visit.tags, s.left, s.owed, s.active, busy || s.visit.changed, swaps + s.visit.swap, order,
          after_f);
      order.pop_back();
    });
  }
};

/// The whole order of a cycle from its changing visits: every other listed
/// facet at its first moment not there or inert (a facet visited later
/// waits for its turn).
template <int W>
std::vector<Facet> whole_order(Space<W>& space, Bits<W> cells, Bits<W> tags, Bits<W> left,
                               const std::vector<int>& changing)
{
  std::vector<Facet> order;
  for(std::size_t k = 0; k <= changing.size(); ++k)
  {
    Bits<W> later;
    for(std::size_t j = k; j < changing.size(); ++j) later.set(changing[j]);
    left.minus(later).for_each([&](int f) {
      if(space.changes(cells, tags, f)) return;
      order.push_back(space.facet(f));
      left.reset(f);
    });
    if(k == changing.size()) break;
    if(!space.changes(cells, tags, changing[k])) throw std::logic_error("a changing visit that changes nothing");
    const auto v = space.visit(cells, tags, changing[k]);
    order.push_back(space.facet(changing[k]));
    left.reset(changing[k]);
    cells = v.cells;
    tags = v.tags;
  }
  if(!left.empty()) throw std::logic_error("a listed facet without a turn");
  return order;
}

/// What `search` found beyond adversarial_search's answer.
struct Closure : Loop_found
{
  std::size_t states_that_can_end = 0;   // states from which one cycle can end the run
  std::size_t states_reaching_end = 0;   // states from which some sequence of cycles ends it
  bool fewest_swaps_searched = false;    // the loop kept has the fewest swaps (small graphs only)
  std::size_t transitions = 0;
};

// The graph of states at cycles' ends of one point set under one reading,
// shared by the starts searched from it: a state's next cycles do not depend
// on where the run started.
template <int W>
class Graph
{
public:
  typedef Bits<W> Set;
  typedef std::function<void(std::size_t, std::size_t, std::size_t)> Progress;

  Graph(const nlohmann::json& header, bool reduce, std::size_t max_nodes)
    : space_(header), reduce_(reduce), max_nodes_(max_nodes)
  {
  }

  /// The search from the cells and tags of `start` (a trace header of the same
  /// points and reading), within `max_states` states reached from it.
  Closure search(const nlohmann::json& start, std::size_t max_states, const Progress& progress)
  {
    Closure result;
    const Checker model(start);
    const std::size_t root = number(space_.cell_set(model.cells()), space_.cell_set(model.tags()));
    // Breadth first from the start, each state's cycle searched once for all starts.
    std::vector<std::size_t> parent(states_.size(), none_); // state -> the state it was reached from
    parent[root] = root;
    std::vector<std::size_t> reached{root};
    const std::size_t nodes_before = nodes_;
    try
    {
      for(std::size_t k = 0; k < reached.size(); ++k)
      {
        const std::size_t u = reached[k];
        expand(u);
        parent.resize(states_.size(), none_);
        for(const Edge& t : out_[u])
          if(parent[t.to] == none_)
          {
            parent[t.to] = u;
            reached.push_back(t.to);
            if(reached.size() > max_states) throw Search_limit_reached();
          }
        if(progress) progress(k + 1, reached.size(), nodes_ - nodes_before);
      }
      result.settled = true;
    }
    catch(const Search_limit_reached&)
    {
    }
    result.nodes = nodes_ - nodes_before;
    result.states = reached.size();
    for(std::size_t u : reached)
      if(expanded(u))
      {
        result.states_that_can_end += can_end_[u];
        result.can_end_off_delaunay = result.can_end_off_delaunay || can_end_off_delaunay_[u];
        result.transitions += out_[u].size();
      }
    if(result.settled)
    {
      // The states of the start's graph from which an end can be reached: backwards from those that can end.
      std::vector<std::vector<std::size_t>> into(states_.size());
      for(std::size_t u : reached)
        for(const Edge& t : out_[u]) into[t.to].push_back(u);
      std::vector<char> reaches(states_.size(), 0);
      std::vector<std::size_t> stack;
      for(std::size_t u : reached)
        if(can_end_[u]) reaches[u] = 1, stack.push_back(u);
      result.states_reaching_end = stack.size();
      while(!stack.empty())
      {
        const std::size_t v = stack.back();
        stack.pop_back();
        for(std::size_t u : into[v])
          if(!reaches[u])
          {
            reaches[u] = 1;
            ++result.states_reaching_end;
            stack.push_back(u);
          }
      }
      result.ends_with_probability_one = result.states_reaching_end == reached.size();
    }
    find_loop(result, start, root, reached, parent);
    return result;
  }

private:
  struct Edge
  {
    std::size_t to, swaps;
  };
  struct State_hash
  {
    std::size_t operator()(const std::pair<Set, Set>& s) const
    {
      return std::size_t(s.first.hash() ^ (s.second.hash() * 31));
    }
  };

  std::size_t number(const Set& cells, const Set& tags)
  {
    const auto [it, added] = index_.emplace(std::make_pair(cells, tags), states_.size());
    if(added)
    {
      states_.emplace_back(cells, tags);
      out_.emplace_back();
      can_end_.push_back(0);
      can_end_off_delaunay_.push_back(0);
      expanded_.push_back(0);
    }
    return it->second;
  }
  bool expanded(std::size_t u) const { return expanded_[u] != 0; }

  // The cycle from state u, searched: its ends numbered as states, in the
  // order of the ends' cells and tags.
  Cycle_search<W> cycle_from(std::size_t u)
  {
    const Set cells = states_[u].first, tags = space_.round_start_tags(states_[u].second);
    Cycle_search<W> cycle{space_, max_nodes_, reduce_};
    cycle.run(cells, tags, space_.listed(cells));
    return cycle;
  }

  void expand(std::size_t u)
  {
    if(expanded(u)) return;
    Cycle_search<W> cycle = cycle_from(u);
    nodes_ += cycle.nodes;
    std::vector<Edge> edges;
    for(const auto& [key, found] : cycle.ends)
      if(std::get<2>(key)) // a busy cycle; an idle one ends the run
        edges.push_back({number(std::get<0>(key), std::get<1>(key)), found.first});
    out_[u] = std::move(edges);
    can_end_[u] = cycle.can_end;
    can_end_off_delaunay_[u] = cycle.can_end_off_delaunay;
    expanded_[u] = 1;
  }

  // The whole order of the cycle from u to v, found again by searching the cycle.
  std::vector<Facet> order_between(std::size_t u, std::size_t v)
  {
    Cycle_search<W> cycle = cycle_from(u);
    const Set cells = states_[u].first, tags = space_.round_start_tags(states_[u].second);
    const auto& found = cycle.ends.at(std::make_tuple(states_[v].first, states_[v].second, true));
    return whole_order(space_, cells, tags, space_.listed(cells), found.second);
  }

  // The way back from t.to to u by fewest cycles (breadth first), as the
  // states u, t.to, ..., u; empty if there is none. It depends on the graph
  // alone, not on the start, so its swaps are kept for every start.
  std::vector<std::size_t> way_back(std::size_t u, const Edge& t)
  {
    std::unordered_map<std::size_t, std::size_t> back{{t.to, t.to}};
    std::queue<std::size_t> q;
    q.push(t.to);
    while(!q.empty() && !back.count(u))
    {
      const std::size_t x = q.front();
      q.pop();
      if(!expanded(x)) continue;
      for(const Edge& e : out_[x])
        if(back.emplace(e.to, x).second) q.push(e.to);
    }
    if(!back.count(u)) return {};
    std::vector<std::size_t> path{u};
    for(std::size_t x = u; x != t.to; x = back.at(x)) path.insert(path.begin() + 1, back.at(x));
    path.push_back(u);
    return path;
  }
  // The strongly connected components of the graph of `reached` (closed
  // under transitions: every state a transition of a searched state goes to
  // is in it), by Tarjan's algorithm without recursion: state -> component.
  std::vector<std::size_t> components(const std::vector<std::size_t>& reached) const
  {
    std::vector<std::size_t> index(states_.size(), none_), low(states_.size()), component(states_.size(), none_);
    std::vector<std::size_t> stack;
    std::vector<char> on_stack(states_.size(), 0);
    std::size_t next_index = 0, next_component = 0;
    for(std::size_t root : reached)
    {
      if(index[root] != none_) continue;
      std::vector<std::pair<std::size_t, std::size_t>> calls{{root, 0}}; // state, next edge
      index[root] = low[root] = next_index++;
      stack.push_back(root);
      on_stack[root] = 1;
      while(!calls.empty())
      {
        auto& [v, k] = calls.back();
        const std::vector<Edge>& edges = expanded(v) ? out_[v] : no_edges_;
        if(k < edges.size())
        {
          const std::size_t w = edges[k++].to;
          if(index[w] == none_)
          {
            index[w] = low[w] = next_index++;
            stack.push_back(w);
            on_stack[w] = 1;
            calls.emplace_back(w, 0);
          }
          else if(on_stack[w])
            low[v] = std::min(low[v], index[w]);
          continue;
        }
        if(low[v] == index[v])
        {
          std::size_t w;
          do
          {
            w = stack.back();
            stack.pop_back();
            on_stack[w] = 0;
            component[w] = next_component;
          } while(w != v);
          ++next_component;
        }
        const std::size_t done = v;
        calls.pop_back();
        if(!calls.empty()) low[calls.back().first] = std::min(low[calls.back().first], low[done]);
      }
    }
    return component;
  }

  std::size_t swaps_between(std::size_t u, std::size_t v) const
  {
    for(const Edge& e : out_[u])
      if(e.to == v) return e.swaps;
    throw std::logic_error("no such cycle");
  }

  // A loop: a transition u -> v with a swap and a way back from v to u. With
  // at most 2,000 states, the one with the fewest swaps (its way back by
  // fewest cycles); otherwise the first found.
  void find_loop(Closure& result, const nlohmann::json& start, std::size_t root, const std::vector<std::size_t>& reached,
                 const std::vector<std::size_t>& parent)
  {
    result.fewest_swaps_searched = reached.size() <= 2000;
    constexpr std::size_t none = std::numeric_limits<std::size_t>::max();
    const std::vector<std::size_t> component = components(reached);
    std::size_t best = none, best_u = 0, best_k = 0;
    for(std::size_t u : reached)
    {
      if(!expanded(u)) continue;
      for(std::size_t k = 0; k < out_[u].size(); ++k)
      {
        const Edge& t = out_[u][k];
        // A transition is on a loop exactly when it stays in its strongly connected component.
        if(t.swaps == 0 || !expanded(t.to) || component[u] != component[t.to]) continue;
        const auto key = std::make_pair(u, k);
        auto known = loop_swaps_.find(key);
        if(known == loop_swaps_.end())
        {
          const std::vector<std::size_t> path = way_back(u, t);
          std::size_t swaps = path.empty() ? none : 0;
          for(std::size_t j = 0; j + 1 < path.size(); ++j) swaps += swaps_between(path[j], path[j + 1]);
          known = loop_swaps_.emplace(key, swaps).first;
        }
        if(known->second < best)
        {
          best = known->second;
          best_u = u;
          best_k = k;
          if(!result.fewest_swaps_searched) break;
        }
      }
      if(best != none && !result.fewest_swaps_searched) break;
    }
    if(best == none) return;
    const std::vector<std::size_t> cycle = way_back(best_u, out_[best_u][best_k]);
    std::vector<std::vector<Facet>> lead; // the start -> u
    for(std::size_t x = best_u; x != root; x = parent[x]) lead.insert(lead.begin(), order_between(parent[x], x));
    std::vector<std::vector<Facet>> loop;
    for(std::size_t k = 0; k + 1 < cycle.size(); ++k) loop.push_back(order_between(cycle[k], cycle[k + 1]));
    std::vector<std::vector<Facet>> path = lead;
    for(int pass = 0; pass < 2; ++pass) path.insert(path.end(), loop.begin(), loop.end());
    result.loop = true;
    result.loop_swaps = best;
    result.loop_cycles = loop.size();
    result.trace = adversarial_search::write_trace(start, path);
  }

  struct Pair_hash
  {
    std::size_t operator()(const std::pair<std::size_t, std::size_t>& p) const
    {
      return std::size_t(p.first * 0x9E3779B97F4A7C15ull ^ p.second);
    }
  };
  Space<W> space_;
  bool reduce_;
  std::size_t max_nodes_, nodes_ = 0;
  std::vector<std::pair<Set, Set>> states_;
  std::unordered_map<std::pair<Set, Set>, std::size_t, State_hash> index_;
  std::vector<std::vector<Edge>> out_;
  std::vector<char> can_end_, can_end_off_delaunay_, expanded_;
  std::unordered_map<std::pair<std::size_t, std::size_t>, std::size_t, Pair_hash> loop_swaps_; // (u, k) -> swaps of its loop
  const std::vector<Edge> no_edges_;
  static constexpr std::size_t none_ = std::numeric_limits<std::size_t>::max();
};

/// The searches from `starts` (trace headers of the same points and reading),
/// sharing one graph, each within `max_states` states at cycles'
/// ends and `max_nodes` nodes in one cycle's search (0: 64 x max_states).
/// `progress(done, states, nodes)` is called after each state's cycle is searched.
inline std::vector<Closure> search_all(const std::vector<nlohmann::json>& starts, std::size_t max_states,
                                       bool reduce = true, std::size_t max_nodes = 0,
                                       const std::function<void(std::size_t, std::size_t, std::size_t, std::size_t)>&
                                           progress = {})
{
  if(starts.empty()) return {};
  if(max_nodes == 0) max_nodes = max_states * 64;
  auto with = [&](auto words) {
    constexpr int W = decltype(words)::value;
    Graph<W> graph(starts.front(), reduce, max_nodes);
    std::vector<Closure> results;
    for(std::size_t k = 0; k < starts.size(); ++k)
      results.push_back(graph.search(starts[k], max_states, [&](std::size_t done, std::size_t found, std::size_t nodes) {
        if(progress) progress(k, done, found, nodes);
      }));
    return results;
  };
  try { return with(std::integral_constant<int, 4>()); }
  catch(const Too_many_numbers&) {}
  try { return with(std::integral_constant<int, 16>()); }
  catch(const Too_many_numbers&) {}
  return with(std::integral_constant<int, 64>());
}

/// The search from the start of `header` alone.
inline Closure search(const nlohmann::json& header, std::size_t max_states, bool reduce = true, std::size_t max_nodes = 0)
{
  return search_all({header}, max_states, reduce, max_nodes).front();
}

} // namespace effective_visit_search

#endif // EDGE_SWAPPING_3_LABORATORY_EFFECTIVE_VISIT_SEARCH_H
