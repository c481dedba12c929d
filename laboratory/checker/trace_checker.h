// SPDX-License-Identifier: GPL-3.0-or-later
// An independent checker of the laboratory's traces (laboratory/doc/traces.md).
//
// It shares no code with the drivers, the taxonomy or the package's
// predicates: its triangulation is a set of cells, each the sorted numbers of
// its four points, its tags a set of such cells, and every decision is made
// again here from CGAL's exact kernel predicates (orientation, in-sphere) and
// the symbolic perturbation of Devillers and Teillaud written out anew. It
// replays a trace line by line and fails at the first line it cannot confirm:
// a facet that is not there, a wrong configuration, a tag read or set wrongly,
// a swap made or left out against the rule, a visit out of the fixed order, a
// state at a round's end that differs. Under the fixed order (priority), a
// state (cells and tags) at a round's end that comes back at a later round's
// end, with swaps in between, certifies that the run loops forever: the order
// and the rule are functions of that state alone. Under an adversarial order
// (chosen by a search) it certifies that repeating the same choices loops.
//
// Its `decide` and `apply` are also the model that the adversarial search
// (laboratory/programs/experiment_adversarial_orders.cpp) drives.
//
// Configurations with four coplanar points among the five are checked too:
// the 2-2 flip on the hull and the 4-4 flip inside, found by walking around
// the edge through the cell set, and every flip must keep the volume, exactly.
// What it does not check: in the storage and random orders, which facet comes
// next. It checks that each round visits listed facets at most once each, and
// every listed facet that was there throughout the round (one gone at some
// moment may have had its turn then). An adversarial order with same-cycle
// is a sweep the adversary chooses: any vertex triple at most once a round.
//
// Traces of the work queue (schedule "queue", the package's reading): each
// visit is checked as above; within a round of the fixed order the
// priorities increase; round 1 visits every facet of the start that no flip
// of that round touched; and the run's end is checked to be a fixed point:
// the rule, decided here on every interior facet, neither swaps nor tags. Which
// facets a round holds is the driver's bookkeeping and is not checked, so
// loops of the work queue are not certified. Plain swapping's first round
// starts with a scan (the in-sphere test alone): its lines ("scan": true)
// come first and must find their facets locally Delaunay.

#ifndef EDGE_SWAPPING_3_LABORATORY_TRACE_CHECKER_H
#define EDGE_SWAPPING_3_LABORATORY_TRACE_CHECKER_H

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpzf.h>
#include <nlohmann/json.hpp>
#include <algorithm>
#include <cmath>
#include <array>
#include <cstdint>
#include <cstring>
#include <istream>
#include <optional>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace trace_checker {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K; // exact predicates
// Exact volumes: a double is m 2^e, and sums, differences and products of such
// numbers are exact in GMP's mpz-based floats, without the rationals' gcds.
typedef CGAL::Gmpzf Exact;
typedef std::array<Exact, 3> Exact_point;
typedef K::Point_3 Point;
typedef std::array<std::size_t, 4> Cell;  // sorted point numbers
typedef std::array<std::size_t, 3> Facet; // sorted point numbers

/// What a check found.
struct Result
{
  bool ok = false;
  std::string error;           ///< the first line that failed, and why
  std::size_t visits = 0;      ///< visits confirmed
  std::size_t rounds = 0;      ///< rounds confirmed
  std::size_t swaps = 0;
  std::string end;             ///< the trace's ending, confirmed
  bool loop_certified = false; ///< priority order: a state came back
  std::size_t loop_from = 0, loop_to = 0; ///< the state after round `loop_from` is the state after round `loop_to`
  std::size_t loop_swaps = 0;  ///< the swaps of rounds `loop_from` + 1 to `loop_to`: one turn of the loop
  bool ends_on_delaunay = false; ///< the last state is CGAL's Delaunay triangulation of the points
};

struct Failure : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

inline void require(bool condition, const std::string& what)
{
  if(!condition) throw Failure(what);
}

// ---- the fixed order, as the format defines it ----

inline std::uint64_t mix(std::uint64_t x)
{
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

inline std::uint64_t bits(double d)
{
  d += 0.0; // -0 is +0
  std::uint64_t b;
  std::memcpy(&b, &d, 8);
  return b;
}

inline std::uint64_t point_key(std::uint64_t seed, const Point& p)
{
  return mix(mix(mix(seed ^ bits(p.x())) ^ bits(p.y())) ^ bits(p.z()));
}

/// A whole number of the trace: a JSON number that is a non-negative integer
/// (a float, a negative or a huge number is a Failure, not a conversion). A
/// parsed trace holds them as unsigned; a header made in C++ from `int`
/// literals (the adversarial search's) holds them as signed.
inline std::uint64_t whole(const nlohmann::json& j)
{
  require(j.is_number_unsigned() || (j.is_number_integer() && j.get<std::int64_t>() >= 0),
          "a number that is not a whole number");
  return j.get<std::uint64_t>();
}

// ---- the state ----

class Checker
{
public:
  explicit Checker(const nlohmann::json& header)
  {
    require(header.value("format", "") == "Edge_swapping_3 visit trace" && header.value("version", 0) == 1,
            "not a version 1 trace");
    strategy_ = header.at("strategy").get<std::string>();
    require(strategy_ == "helper" || strategy_ == "plain", "unknown strategy '" + strategy_ + "'");
    order_ = header.at("order").get<std::string>();
    // "adversarial": any order chosen visit by visit (by a search,
    // experiment_adversarial_orders): with next-cycle, each facet listed at a
    // round's start at most once; with same-cycle, any facet at most once.
    require(order_ == "storage" || order_ == "random" || order_ == "priority" || order_ == "adversarial",
            "unknown order '" + order_ + "'");
    const std::string schedule = header.value("schedule", "");
    require(schedule == "cycles" || schedule == "queue", "the schedule is 'cycles' or 'queue'");
    queue_ = schedule == "queue";
    seed_ = whole(header.at("seed"));
    // The reading of Algorithm 4: tag lifetime, swap condition, ending (traces.md).
    std::vector<std::string> reading(1);
    for(char ch : header.at("reading").get<std::string>())
      if(ch == ',') reading.emplace_back();
      else reading.back() += ch;
    require(reading.size() == 3 || reading.size() == 4, "a reading is three or four names");
    if(reading.size() == 3) reading.push_back("next-cycle");
    const std::string lifetime = reading[0], condition = reading[1], ending = reading[2], made = reading[3];
    require(lifetime == "until-destroyed" || lifetime == "cleared-each-cycle" || lifetime == "never-cleared",
            "unknown tag lifetime");
    require(condition == "pass-over" || condition == "any-tetrahedron" || condition == "facet-cells",
            "unknown swap condition");
    require(ending == "no-swap-no-tag" || ending == "no-swap", "unknown ending rule");
    require(made == "next-cycle" || made == "same-cycle", "unknown visit of made facets");
    clear_tags_each_cycle_ = lifetime == "cleared-each-cycle";
    tags_outlive_cells_ = lifetime == "never-cleared";
    pass_over_ = condition != "any-tetrahedron";
    facet_cells_ = condition == "facet-cells";
    end_without_swap_ = ending == "no-swap";
    sweep_ = made == "same-cycle";
    require(!sweep_ || order_ == "priority" || order_ == "random" || order_ == "adversarial",
            "same-cycle needs the priority, random or adversarial order");
    sweep_in_order_ = sweep_ && order_ != "adversarial";
    // Random sweeps: cycle k's seed is m(m(seed) + k) in traces that say so
    // ("sweep_seeds" in the header), m(seed + k) in older ones (traces.md).
    if(header.contains("sweep_seeds"))
    {
      require(header.at("sweep_seeds") == "m(m(seed) + cycle)", "unknown sweep_seeds");
      require(order_ == "random" && sweep_, "sweep_seeds belongs to random order with same-cycle");
      mixed_sweep_seeds_ = true;
    }
    require(!queue_ || (!clear_tags_each_cycle_ && !tags_outlive_cells_ && pass_over_ && !facet_cells_ &&
                        !end_without_swap_ && !sweep_ && order_ != "adversarial"),
            "the work queue runs the package's reading, in storage, random or priority order");
    max_rounds_ = std::size_t(whole(header.at("max_rounds")));
    for(const auto& p : header.at("points"))
    {
      require(p.is_array() && p.size() == 3, "a point is not three numbers");
      const double x = p.at(0).get<double>(), y = p.at(1).get<double>(), z = p.at(2).get<double>();
      // Exact arithmetic needs finite coordinates; the package's range is 1e-30 to 1e30.
      for(double v : {x, y, z}) require(std::isfinite(v) && std::abs(v) <= 1e30, "a coordinate that is not finite or beyond 1e30");
      points_.emplace_back(x, y, z);
      exact_points_.push_back({Exact(x), Exact(y), Exact(z)}); // once, not at every flip
    }
    for(const auto& c : header.at("cells")) add_cell(cell_of(c));
    check_start();
    if(queue_)
      for(const Facet& f : interior_facets()) unvisited_start_.insert(f);
    begin_round();
  }

  /// Checks one line after the header.
  void line(const nlohmann::json& l, Result& result)
  {
    require(!ended_, "a line after the end");
    require(l.contains("end") || result.rounds == 0 || !last_round_idle_,
            "a line after a round that ended the run under the reading's ending rule");
    if(l.contains("facet"))
      visit(l, result);
    else if(l.contains("round"))
      end_round(l, result);
    else if(l.contains("end"))
      end(l, result);
    else
      throw Failure("a line that is neither a visit, a round's end nor the end");
  }

  bool ended() const { return ended_; }

private:
  // ---- geometry, exactly ----

  CGAL::Orientation orientation(std::size_t a, std::size_t b, std::size_t c, std::size_t d) const
  {
    return CGAL::orientation(points_[a], points_[b], points_[c], points_[d]);
  }

  /// The cell's numbers in an order that is positively oriented.
  Cell oriented(const Cell& t) const
  {
    Cell o = t;
    const CGAL::Orientation s = orientation(o[0], o[1], o[2], o[3]);
    require(s != CGAL::COPLANAR, "a flat cell");
    if(s == CGAL::NEGATIVE) std::swap(o[0], o[1]);
    return o;
  }

  /// Whether point e is inside the sphere of the positively oriented cell t,
  /// ties broken as Devillers and Teillaud perturb: the points, from the
  /// lexicographically largest down, are lifted by ever smaller amounts; the
  /// first whose lift decides gives the side.
  bool inside_sphere(const Cell& t, std::size_t e) const
  {
    const CGAL::Oriented_side s =
      CGAL::side_of_oriented_sphere(points_[t[0]], points_[t[1]], points_[t[2]], points_[t[3]], points_[e]);
    if(s != CGAL::ON_ORIENTED_BOUNDARY) return s == CGAL::ON_POSITIVE_SIDE;
    std::array<std::size_t, 5> p{t[0], t[1], t[2], t[3], e};
    std::sort(p.begin(), p.end(), [&](std::size_t a, std::size_t b) {
      return CGAL::compare_xyz(points_[a], points_[b]) == CGAL::LARGER;
    });
    for(std::size_t q : p)
    {
      if(q == e) return false; // the query's own lift puts it outside
      Cell r = t;
      for(auto& v : r)
        if(v == q) v = e;
      const CGAL::Orientation o = orientation(r[0], r[1], r[2], r[3]);
      if(o != CGAL::COPLANAR) return o == CGAL::POSITIVE;
    }
    throw Failure("the perturbation did not decide (five coplanar points)");
  }

  // ---- combinatorics ----

  static Cell sorted(Cell t)
  {
    std::sort(t.begin(), t.end());
    return t;
  }

  Cell cell_of(const nlohmann::json& c) const
  {
    require(c.is_array() && c.size() == 4, "a cell is four point numbers");
    Cell t;
    for(int k = 0; k < 4; ++k)
    {
      t[k] = std::size_t(whole(c.at(k)));
      require(t[k] < points_.size(), "a point number out of range");
    }
    t = sorted(t);
    require(t[0] != t[1] && t[1] != t[2] && t[2] != t[3], "a cell with a repeated point");
    return t;
  }

  std::set<Cell> cell_set(const nlohmann::json& list) const
  {
    std::set<Cell> s;
    for(const auto& c : list) require(s.insert(cell_of(c)).second, "a cell listed twice");
    return s;
  }

  static std::array<Facet, 4> facets_of(const Cell& t)
  {
    return {Facet{t[1], t[2], t[3]}, Facet{t[0], t[2], t[3]}, Facet{t[0], t[1], t[3]}, Facet{t[0], t[1], t[2]}};
  }

  static std::size_t apex(const Cell& t, const Facet& f)
  {
    for(std::size_t v : t)
      if(v != f[0] && v != f[1] && v != f[2]) return v;
    throw Failure("a cell without the apex of its facet");
  }

  void add_cell(const Cell& t)
  {
    require(cells_.insert(t).second, "a cell made twice");
    for(const Facet& f : facets_of(t))
    {
      auto& holders = facets_[f];
      require(holders.size() < 2, "a facet in three cells");
      holders.push_back(t);
    }
  }

  void remove_cell(const Cell& t)
  {
    require(cells_.erase(t) == 1, "a cell removed that is not there");
    if(!tags_outlive_cells_) tags_.erase(t);
    for(const Facet& f : facets_of(t))
    {
      auto& holders = facets_[f];
      holders.erase(std::find(holders.begin(), holders.end(), t));
      if(holders.empty()) facets_.erase(f);
    }
  }

  bool is_interior(const Facet& f) const
  {
    const auto it = facets_.find(f);
    return it != facets_.end() && it->second.size() == 2;
  }

  /// The start is a triangulation of the points' convex hull: no flat cell,
  /// each facet in at most two cells with their apexes on opposite sides, and
  /// the cells' volumes add up to the hull's.
  void check_start() const
  {
    const Exact cells_volume = volume(std::vector<Cell>(cells_.begin(), cells_.end()));
    for(const auto& [f, holders] : facets_)
      if(holders.size() == 2)
        require(orientation(f[0], f[1], f[2], apex(holders[0], f)) == -orientation(f[0], f[1], f[2], apex(holders[1], f)),
                "two cells on the same side of a facet in the start");
    CGAL::Delaunay_triangulation_3<K> hull(points_.begin(), points_.end()); // its cells fill the hull; exact predicates
    auto exact = [](const Point& p) { return Exact_point{Exact(p.x()), Exact(p.y()), Exact(p.z())}; };
    Exact hull_volume = 0;
    for(auto c : hull.finite_cell_handles())
      hull_volume += six_volume(exact(c->vertex(0)->point()), exact(c->vertex(1)->point()),
                                exact(c->vertex(2)->point()), exact(c->vertex(3)->point()));
    require(cells_volume == hull_volume, "the start's cells do not fill the convex hull once");
  }

  // ---- rounds and the fixed order ----

  /// The place of facet f in a sweep: its priority, then its points in lexicographic order.
  struct Place
  {
    std::uint64_t key;
    Facet by_points;
  };

  Place place_of(const Facet& f) const
  {
    Place p{0, f};
    std::sort(p.by_points.begin(), p.by_points.end(), [&](std::size_t a, std::size_t b) {
      return CGAL::compare_xyz(points_[a], points_[b]) == CGAL::SMALLER;
    });
    p.key = mix(point_key(sweep_seed_, points_[f[0]]) + point_key(sweep_seed_, points_[f[1]]) +
                point_key(sweep_seed_, points_[f[2]]));
    return p;
  }

  bool before(const Place& a, const Place& b) const
  {
    if(a.key != b.key) return a.key < b.key;
    for(int k = 0; k < 3; ++k)
      if(a.by_points[k] != b.by_points[k])
        return CGAL::compare_xyz(points_[a.by_points[k]], points_[b.by_points[k]]) == CGAL::SMALLER;
    return false;
  }

  /// The fixed order's key of facet `f`, and its points sorted lexicographically (the tie-break).
  std::uint64_t priority(const Facet& f) const
  {
    return mix(point_key(seed_, points_[f[0]]) + point_key(seed_, points_[f[1]]) + point_key(seed_, points_[f[2]]));
  }
  std::array<std::size_t, 3> by_points(const Facet& f) const
  {
    std::array<std::size_t, 3> s = f;
    std::sort(s.begin(), s.end(), [&](std::size_t a, std::size_t b) {
      return CGAL::compare_xyz(points_[a], points_[b]) == CGAL::SMALLER;
    });
    return s;
  }
  bool priority_before(const std::pair<std::uint64_t, std::array<std::size_t, 3>>& a,
                       const std::pair<std::uint64_t, std::array<std::size_t, 3>>& b) const
  {
    if(a.first != b.first) return a.first < b.first;
    for(int k = 0; k < 3; ++k)
      if(a.second[k] != b.second[k]) return CGAL::compare_xyz(points_[a.second[k]], points_[b.second[k]]) == CGAL::SMALLER;
    return false;
  }

  void begin_round()
  {
    queue_last_.reset();
    if(clear_tags_each_cycle_) tags_.clear();
    ++round_number_;
    if(sweep_in_order_)
    {
      // A sweep (same-cycle): priority order, or in random order one drawn from the seed and the round.
      sweep_seed_ = order_ == "priority" ? seed_ : mix((mixed_sweep_seeds_ ? mix(seed_) : seed_) + round_number_);
      ahead_.clear();
      for(const auto& [f, holders] : facets_)
        if(holders.size() == 2) ahead_.push_back(place_of(f));
      std::sort(ahead_.begin(), ahead_.end(), [&](const Place& a, const Place& b) { return before(a, b); });
      round_swaps_ = 0;
      round_tags_ = 0;
      return;
    }
    listed_.clear();
    for(const auto& [f, holders] : facets_)
      if(holders.size() == 2) listed_.push_back(f);
    if(order_ == "priority")
      std::sort(listed_.begin(), listed_.end(), [&](const Facet& a, const Facet& b) {
        return priority_before({priority(a), by_points(a)}, {priority(b), by_points(b)});
      });
    listed_set_ = std::set<Facet>(listed_.begin(), listed_.end());
    owed_ = listed_set_;
    next_ = 0;
    visited_.clear();
    round_swaps_ = 0;
    round_tags_ = 0;
  }

  /// Priority order: the next listed facet that exists now must be `f`.
  void check_turn(const Facet& f)
  {
    if(queue_)
    {
      if(round_number_ == 1) unvisited_start_.erase(f);
      if(order_ == "priority")
      {
        const std::pair<std::uint64_t, std::array<std::size_t, 3>> key{priority(f), by_points(f)};
        require(!queue_last_ || priority_before(*queue_last_, key), "a visit out of the fixed order in its round");
        queue_last_ = key;
      }
      return;
    }
    if(sweep_in_order_)
    {
      while(!ahead_.empty() && !is_interior(sorted_of(ahead_.front().by_points))) ahead_.erase(ahead_.begin());
      require(!ahead_.empty() && sorted_of(ahead_.front().by_points) == f, "a visit out of the sweep's order");
      current_ = ahead_.front();
      ahead_.erase(ahead_.begin());
      return;
    }
    if(order_ != "priority")
    {
      // An adversarial sweep (same-cycle) may visit a facet made in the round;
      // a vertex triple has one place in a sweep, so it is visited once.
      require(sweep_ || listed_set_.count(f) == 1, "a facet visited that was not there when the round began");
      require(visited_.insert(f).second, "a facet visited twice in one round");
      owed_.erase(f);
      return;
    }
    while(next_ < listed_.size() && !is_interior(listed_[next_])) ++next_;
    require(next_ < listed_.size() && listed_[next_] == f, "a visit out of the fixed order");
    ++next_;
  }

  // ---- the planar configurations ----

  static std::array<std::size_t, 2> other_two(const Facet& f, std::size_t v)
  {
    std::array<std::size_t, 2> xy{};
    int m = 0;
    for(std::size_t w : f)
      if(w != v) xy[m++] = w;
    return xy;
  }

  /// Six times the signed volume of the tetrahedron p q r s, exactly.
  static Exact six_volume(const Exact_point& p, const Exact_point& q, const Exact_point& r, const Exact_point& s)
  {
    Exact d[3][3];
    for(int k = 0; k < 3; ++k)
    {
      d[0][k] = q[k] - p[k];
      d[1][k] = r[k] - p[k];
      d[2][k] = s[k] - p[k];
    }
    return d[0][0] * (d[1][1] * d[2][2] - d[1][2] * d[2][1]) - d[0][1] * (d[1][0] * d[2][2] - d[1][2] * d[2][0]) +
           d[0][2] * (d[1][0] * d[2][1] - d[1][1] * d[2][0]);
  }

  /// Six times the cells' total volume, exactly.
  Exact volume(const std::vector<Cell>& cells) const
  {
    Exact sum = 0;
    for(const Cell& t : cells)
    {
      const Cell o = oriented(t);
      sum += six_volume(exact_points_[o[0]], exact_points_[o[1]], exact_points_[o[2]], exact_points_[o[3]]);
    }
    return sum;
  }

  /// Point e lies in the plane of d and the edge (x, y) of facet f opposite z,
  /// across (x, y) from d: the quadrilateral x d y e is convex, and the edge
  /// (x, y) can give way to (d, e) if its cells are (x, y, z, d), (x, y, z, e)
  /// and either two more, (x, y, w, d) and (x, y, w, e), closing the ring
  /// around it (4-4), or none, both quadrilateral's triangles on the hull
  /// (2-2). Walks around (x, y) through the cell set to find out.
  std::string planar_flip(const Facet& f, std::size_t z, std::size_t d, std::size_t e, std::vector<Cell>& old_cells,
                          std::vector<Cell>& new_cells, std::string& flip_name) const
  {
    const auto xy = other_two(f, z);
    const std::size_t x = xy[0], y = xy[1];
    // The ring of (x, y) from z through d: the cell across facet (x, y, current).
    std::vector<std::size_t> ring{z, d};
    bool closed = false;
    for(std::size_t guard = 0; guard <= cells_.size(); ++guard)
    {
      const std::size_t prev = ring[ring.size() - 2], current = ring.back();
      const Facet across = sorted_facet(x, y, current);
      const auto it = facets_.find(across);
      if(it == facets_.end() || it->second.size() < 2) break; // the hull
      const Cell from = sorted({x, y, prev, current});
      const Cell& next = it->second[0] == from ? it->second[1] : it->second[0];
      const std::size_t w = apex(next, across);
      if(w == z)
      {
        closed = true;
        break;
      }
      ring.push_back(w);
    }
    std::vector<std::size_t> sides; // the apexes of the new cells beside z
    if(closed && ring.size() == 4 && ring[3] == e)
    {
      flip_name = "4-4";
      sides = {z, ring[2]};
    }
    else if(!closed && ring.size() == 2 && !is_interior(sorted_facet(x, y, e)))
    {
      flip_name = "2-2";
      sides = {z};
    }
    else
      return "planar unswappable";
    for(std::size_t s : sides)
      for(std::size_t v : {d, e})
        old_cells.push_back(sorted({x, y, s, v}));
    for(std::size_t s : sides)
      for(std::size_t v : {x, y})
        new_cells.push_back(sorted({d, e, s, v}));
    for(const Cell& t : new_cells)
      if(orientation(t[0], t[1], t[2], t[3]) == CGAL::COPLANAR)
      {
        old_cells.clear();
        new_cells.clear();
        flip_name.clear();
        return "planar unswappable";
      }
    return flip_name == "4-4" ? "planar 4-4" : "planar hull 2-2";
  }

  static Facet sorted_facet(std::size_t a, std::size_t b, std::size_t c)
  {
    Facet t{a, b, c};
    std::sort(t.begin(), t.end());
    return t;
  }

  static Facet sorted_of(Facet f)
  {
    std::sort(f.begin(), f.end());
    return f;
  }

  /// A sweep: the facets a flip made whose place is still ahead join it.
  void add_made_facets(const std::vector<Cell>& made)
  {
    for(const Cell& t : made)
      for(const Facet& f : facets_of(t))
      {
        if(!is_interior(f)) continue;
        const Place p = place_of(f);
        if(!before(current_, p)) continue;
        const auto at = std::lower_bound(ahead_.begin(), ahead_.end(), p,
                                         [&](const Place& a, const Place& b) { return before(a, b); });
        if(at == ahead_.end() || before(p, *at)) ahead_.insert(at, p);
      }
  }

  // ---- a visit ----

public:
  /// What the rule does at one visit, decided here from the state alone.
  struct Decision
  {
    Facet facet;
    std::size_t d = 0, e = 0; // the apexes
    bool delaunay = false;
    std::set<Cell> five_cells;
    std::string kind, flip_name;
    std::vector<Cell> old_cells, new_cells;
    std::set<Cell> new_tags;
    bool swap = false;
  };

  /// The decision at interior facet `f` seen with apex `d` first.
  Decision decide(const Facet& f, std::size_t d, std::size_t e) const
  {
    Decision r;
    r.facet = f;
    r.d = d;
    r.e = e;
    const Cell cd = sorted({f[0], f[1], f[2], d});
    // Locally Delaunay: e outside the (perturbed) sphere of the cell with d.
    r.delaunay = !inside_sphere(oriented(cd), e);

    // The cells made of the five points.
    const std::array<std::size_t, 5> five{f[0], f[1], f[2], d, e};
    for(int skip = 0; skip < 5; ++skip)
    {
      Cell t;
      int m = 0;
      for(int k = 0; k < 5; ++k)
        if(k != skip) t[m++] = five[k];
      t = sorted(t);
      if(cells_.count(t)) r.five_cells.insert(t);
    }

    // The configuration: the signs of e's barycentric coordinates in the cell with d.
    const Cell o = oriented(cd);
    int positive = 0, negative = 0, zero = 0;
    std::size_t negative_vertex = 0, zero_vertex = 0;
    for(std::size_t v : f)
    {
      Cell q = o;
      for(auto& w : q)
        if(w == v) w = e;
      const CGAL::Orientation s = orientation(q[0], q[1], q[2], q[3]);
      if(s == CGAL::POSITIVE) ++positive;
      else if(s == CGAL::COPLANAR)
      {
        ++zero;
        zero_vertex = v;
      }
      else
      {
        ++negative;
        negative_vertex = v;
      }
    }
    if(positive == 3)
    {
      r.kind = "two tetrahedra convex";
      r.flip_name = "2-3";
      r.old_cells = {cd, sorted({f[0], f[1], f[2], e})};
      for(std::size_t v : f)
      {
        Cell t = cd;
        for(auto& w : t)
          if(w == v) w = e;
        r.new_cells.push_back(sorted(t));
      }
    }
    else if(positive == 2 && negative == 1)
    {
      // Concave at the edge (x, y) opposite the negative vertex z; a 3-2 flip if (x, y, d, e) is a cell.
      const auto xy = other_two(f, negative_vertex);
      const Cell third = sorted({xy[0], xy[1], d, e});
      r.kind = "concave";
      if(cells_.count(third))
      {
        r.kind = "three tetrahedra convex";
        r.flip_name = "3-2";
        r.old_cells = {cd, sorted({f[0], f[1], f[2], e}), third};
        r.new_cells = {sorted({xy[0], negative_vertex, d, e}), sorted({xy[1], negative_vertex, d, e})};
      }
    }
    else if(positive == 2 && zero == 1)
      r.kind = planar_flip(f, zero_vertex, d, e, r.old_cells, r.new_cells, r.flip_name);
    else if(positive == 1 && negative == 2)
      r.kind = r.five_cells.size() == 4 ? "four tetrahedra" : "concave";
    else
      r.kind = "planar unswappable"; // e on the line of an edge, or in a plane and beyond an edge

    // The rule.
    if(strategy_ == "plain")
      r.swap = !r.delaunay && !r.old_cells.empty();
    else
    {
      // The package's reading: a Delaunay facet whose two cells are untagged is passed over.
      const Cell ce = sorted({f[0], f[1], f[2], e});
      const bool passed_over = pass_over_ && r.delaunay && !tags_.count(cd) && !tags_.count(ce);
      if(!passed_over)
      {
        if(!r.delaunay)
          for(const Cell& t : r.five_cells)
            if(!tags_.count(t)) r.new_tags.insert(t);
        const std::vector<Cell> must_be_tagged = facet_cells_ ? std::vector<Cell>{cd, ce} : r.old_cells;
        if(!r.old_cells.empty())
          for(const Cell& t : must_be_tagged)
            if(tags_.count(t) || r.new_tags.count(t)) r.swap = true;
      }
    }
    return r;
  }

  /// Carries out a decision: its tags, and its flip if it swaps.
  void apply(const Decision& r)
  {
    tags_.insert(r.new_tags.begin(), r.new_tags.end());
    round_tags_ += r.new_tags.size();
    if(!r.swap) return;
    require(volume(r.new_cells) == volume(r.old_cells), "the flip does not keep the volume");
    if(queue_ && round_number_ == 1)
      for(const auto* cells : {&r.old_cells, &r.new_cells})
        for(const Cell& t : *cells)
          for(const Facet& f : facets_of(t)) unvisited_start_.erase(f);
    for(const Cell& t : r.old_cells) remove_cell(t);
    for(const Cell& t : r.new_cells)
    {
      oriented(t); // not flat
      add_cell(t);
    }
    if(sweep_in_order_) add_made_facets(r.new_cells);
    ++round_swaps_;
  }

  /// The apexes of interior facet `f`, the one of the cell that holds it (the
  /// lexicographically smaller apex) first, as the drivers see a facet.
  std::pair<std::size_t, std::size_t> apexes(const Facet& f) const
  {
    const auto& holders = facets_.at(f);
    std::size_t d = apex(holders[0], f), e = apex(holders[1], f);
    if(CGAL::compare_xyz(points_[e], points_[d]) == CGAL::SMALLER) std::swap(d, e);
    return {d, e};
  }

  /// The interior facets now.
  std::vector<Facet> interior_facets() const
  {
    std::vector<Facet> out;
    for(const auto& [f, holders] : facets_)
      if(holders.size() == 2) out.push_back(f);
    return out;
  }

  bool has_interior_facet(const Facet& f) const { return is_interior(f); }
  /// Puts the model in the state of `cells` with `tags`, for a program that
  /// searches states (the facets follow the cells; counters are kept).
  void set_state(const std::set<Cell>& cells, const std::set<Cell>& tags)
  {
    cells_.clear();
    facets_.clear();
    for(const Cell& t : cells) add_cell(t);
    tags_ = tags;
  }
  /// Makes the flip of a decision that has one, for a program that searches
  /// states: the removed cells' tags go with them as in a swap, and nothing
  /// else is done (no new tags, no count, no check of the volume).
  void flip(const Decision& r)
  {
    for(const Cell& t : r.old_cells) remove_cell(t);
    for(const Cell& t : r.new_cells) add_cell(t);
  }
  const std::set<Cell>& cells() const { return cells_; }
  const std::set<Cell>& tags() const { return tags_; }
  const std::vector<Point>& points() const { return points_; }
  /// Starts a round as the reading says (tags cleared or not), for a program that drives the model.
  void start_round() { begin_round(); }
  std::size_t round_swaps() const { return round_swaps_; }
  std::size_t round_new_tags() const { return round_tags_; }
  /// Whether a round with these counts ends the run under the reading.
  bool round_is_idle() const { return round_swaps_ == 0 && (round_tags_ == 0 || end_without_swap_); }
  /// Whether the reading ends the run after a round without swaps, new tags or not.
  bool ends_without_swap() const { return end_without_swap_; }
  /// Whether a destroyed cell's tag comes back with it (never-cleared).
  bool tags_outlive_cells() const { return tags_outlive_cells_; }
  /// Whether tags are cleared at each round's start (cleared-each-cycle).
  bool clears_tags_each_cycle() const { return clear_tags_each_cycle_; }
  /// Whether facets made during a round are visited in it (same-cycle).
  bool visits_made_facets() const { return sweep_; }
  /// Whether every interior facet is locally Delaunay (perturbed).
  bool is_delaunay() const { return all_delaunay(); }
  /// How many interior facets are not locally Delaunay (perturbed).
  std::size_t facets_not_delaunay() const
  {
    std::size_t n = 0;
    for(const auto& [f, holders] : facets_)
      n += holders.size() == 2 && inside_sphere(oriented(holders[0]), apex(holders[1], f));
    return n;
  }

private:
  void visit(const nlohmann::json& l, Result& result)
  {
    Facet f;
    for(int k = 0; k < 3; ++k) f[k] = std::size_t(whole(l.at("facet").at(k)));
    std::sort(f.begin(), f.end());
    require(is_interior(f), "a visited facet that is not an interior facet now");
    const bool scan = l.contains("scan");
    if(scan)
    {
      // The work queue's scan in round 1: the in-sphere test alone, before any other visit.
      require(queue_ && round_number_ == 1 && !queue_visited_, "a scan visit out of place");
      require(unvisited_start_.erase(f) == 1, "a scan visit of a facet not in the start, or twice");
    }
    else
    {
      check_turn(f);
      queue_visited_ = true;
    }
    const auto& holders = facets_.at(f);
    const std::size_t d = std::size_t(whole(l.at("apexes").at(0))), e = std::size_t(whole(l.at("apexes").at(1)));
    const std::size_t h0 = apex(holders[0], f), h1 = apex(holders[1], f);
    require((d == h0 && e == h1) || (d == h1 && e == h0), "the apexes are not those of the facet's cells");
    const Decision r = decide(f, d, e);
    require(l.at("delaunay").get<bool>() == r.delaunay, "the in-sphere test says otherwise");
    require(cell_set(l.at("cells")) == r.five_cells, "the cells of the five points are not these");
    const auto& tagged_list = l.at("tagged");
    require(tagged_list.size() == l.at("cells").size(), "a tag flag per cell");
    for(std::size_t k = 0; k < tagged_list.size(); ++k)
      require((whole(tagged_list.at(k)) != 0) == (tags_.count(cell_of(l.at("cells").at(k))) == 1),
              "a tag read wrongly");
    require(l.at("kind").get<std::string>() == r.kind, "the configuration is " + r.kind);
    require(cell_set(l.at("new_tags")) == r.new_tags, "the tags set are not those the rule sets");
    const auto& flip = l.at("flip");
    if(scan) require(r.delaunay && !r.swap && r.new_tags.empty(), "the scan left alone a facet the rule acts on");
    if(!r.swap)
      require(flip.is_null() && l.at("created").empty(), "a swap the rule does not make");
    else
    {
      require(!flip.is_null(), "a swap the rule makes is missing");
      require(flip.get<std::string>() == r.flip_name, "the wrong flip");
      const std::set<Cell> made(r.new_cells.begin(), r.new_cells.end());
      require(cell_set(l.at("created")) == made, "the flip made other cells");
      ++result.swaps;
    }
    apply(r);
    if(r.swap) // a listed facet the flip took away may have had its turn now
      for(const Cell& t : r.old_cells)
        for(const Facet& g : facets_of(t))
          if(!is_interior(g)) owed_.erase(g);
    ++result.visits;
  }

  // ---- a round's end, and the end ----

  void end_round(const nlohmann::json& l, Result& result)
  {
    const std::size_t round = std::size_t(whole(l.at("round")));
    require(round == result.rounds + 1, "rounds out of sequence");
    if(sweep_in_order_)
    {
      while(!ahead_.empty() && !is_interior(sorted_of(ahead_.front().by_points))) ahead_.erase(ahead_.begin());
      require(ahead_.empty(), "the round ended before a facet ahead in the sweep was visited");
    }
    else if(order_ != "priority" && !queue_)
      require(owed_.empty(), "the round ended before a listed facet that was there throughout was visited");
    else if(order_ == "priority" && !queue_)
    {
      while(next_ < listed_.size() && !is_interior(listed_[next_])) ++next_;
      require(next_ == listed_.size(), "the round ended before a listed facet that is still there was visited");
    }
    require(std::size_t(whole(l.at("swaps"))) == round_swaps_, "the round's swap count is wrong");
    require(std::size_t(whole(l.at("new_tags"))) == round_tags_, "the round's count of new tags is wrong");
    require(cell_set(l.at("cells")) == cells_, "the cells at the round's end differ");
    std::set<Cell> tags_of_cells; // never-cleared: tags of destroyed cells are kept, but not listed
    for(const Cell& t : tags_)
      if(cells_.count(t)) tags_of_cells.insert(t);
    require(cell_set(l.at("tagged")) == tags_of_cells, "the tags at the round's end differ");
    if(queue_ && round == 1)
      require(unvisited_start_.empty(), "round 1 of the work queue left a facet of the start unvisited");
    result.rounds = round;
    swaps_after_round_.push_back(result.swaps);
    last_round_idle_ = round_swaps_ == 0 && (round_tags_ == 0 || end_without_swap_);
    // A state that comes back certifies a loop when the visits are a function of
    // the state (the fixed order) or are chosen (an adversary repeats its choices).
    if((order_ == "priority" || order_ == "adversarial") && !queue_ && !result.loop_certified)
    {
      const auto state = std::make_pair(cells_, tags_);
      const auto it = seen_.find(state);
      if(it != seen_.end() && !last_round_idle_)
      {
        result.loop_certified = true;
        result.loop_from = it->second;
        result.loop_to = round;
        result.loop_swaps = result.swaps - swaps_after_round_[it->second];
      }
      else
        seen_.emplace(state, round);
    }
    begin_round();
  }

  bool all_delaunay() const
  {
    for(const auto& [f, holders] : facets_)
      if(holders.size() == 2 && inside_sphere(oriented(holders[0]), apex(holders[1], f))) return false;
    return true;
  }

  void end(const nlohmann::json& l, Result& result)
  {
    const std::string ending = l.at("end").get<std::string>();
    require(std::size_t(whole(l.at("rounds"))) == result.rounds, "the end counts other rounds");
    const bool delaunay = all_delaunay();
    if(queue_ && ending != "cycle limit reached")
      for(const Facet& f : interior_facets())
      {
        const auto [d, e] = apexes(f);
        const Decision r = decide(f, d, e);
        require(!r.swap && r.new_tags.empty(), "the work queue ended, but the rule would still swap or tag a facet");
      }
    if(ending == "converged")
      require(last_round_idle_ && delaunay, "'converged' but the last round changed something or a facet is not Delaunay");
    else if(ending == "stuck")
      require(last_round_idle_ && !delaunay, "'stuck' but the last round changed something or every facet is Delaunay");
    else if(ending == "cycle limit reached")
      require(result.rounds == max_rounds_ && !last_round_idle_, "the round limit was not reached");
    else
      throw Failure("unknown ending '" + ending + "'");
    result.end = ending;
    // The last state against CGAL's Delaunay triangulation, cell for cell.
    CGAL::Delaunay_triangulation_3<K> dt(points_.begin(), points_.end());
    std::map<Point, std::size_t> number;
    for(std::size_t k = 0; k < points_.size(); ++k) number.emplace(points_[k], k);
    std::set<Cell> delaunay_cells;
    for(auto c : dt.finite_cell_handles())
      delaunay_cells.insert(sorted({number.at(c->vertex(0)->point()), number.at(c->vertex(1)->point()),
                                    number.at(c->vertex(2)->point()), number.at(c->vertex(3)->point())}));
    result.ends_on_delaunay = delaunay_cells == cells_;
    ended_ = true;
  }

  std::string strategy_, order_;
  std::uint64_t seed_ = 0;
  std::size_t max_rounds_ = 0;
  std::vector<Point> points_;
  std::vector<Exact_point> exact_points_; // the same points, for exact volumes
  std::set<Cell> cells_, tags_;
  std::map<Facet, std::vector<Cell>> facets_;
  std::vector<Facet> listed_;
  std::set<Facet> listed_set_, visited_;
  // Storage, random and adversarial orders: the facets listed at the round's
  // start that were there at every moment since and are not visited yet. A
  // listed facet that is gone at some moment may have had its turn then; one
  // that never is must be visited before the round ends.
  std::set<Facet> owed_;
  std::size_t next_ = 0, round_swaps_ = 0, round_tags_ = 0;
  std::vector<std::size_t> swaps_after_round_{0}; // the swaps confirmed by the end of each round, from round 0
  bool last_round_idle_ = false, ended_ = false;
  bool queue_ = false;                    // a trace of the work queue
  bool queue_visited_ = false;            // a visit other than the scan's has come
  std::set<Facet> unvisited_start_;       // the queue's round 1: facets of the start not yet visited or touched
  std::optional<std::pair<std::uint64_t, std::array<std::size_t, 3>>> queue_last_; // the queue's last priority
  bool clear_tags_each_cycle_ = false, pass_over_ = true, end_without_swap_ = false;
  bool tags_outlive_cells_ = false, facet_cells_ = false, sweep_ = false;
  bool sweep_in_order_ = false; // a sweep in the fixed or random order (not the adversary's)
  std::size_t round_number_ = 0;
  std::uint64_t sweep_seed_ = 0;
  bool mixed_sweep_seeds_ = false;
  std::vector<Place> ahead_; // a sweep: the places still ahead, in order
  Place current_{0, {}};
  std::map<std::pair<std::set<Cell>, std::set<Cell>>, std::size_t> seen_;
};

/// Checks the trace read from `in`, line by line.
inline Result check_trace(std::istream& in)
{
  Result result;
  std::string text;
  std::size_t number = 0;
  try
  {
    require(bool(std::getline(in, text)), "an empty trace");
    ++number;
    Checker checker(nlohmann::json::parse(text));
    while(std::getline(in, text))
    {
      ++number;
      checker.line(nlohmann::json::parse(text), result);
    }
    require(checker.ended(), "the trace has no end line");
    result.ok = true;
  }
  catch(const std::exception& e) // Failure, and JSON that is not what the format says
  {
    result.ok = false;
    result.error = "line " + std::to_string(number) + ": " + e.what();
  }
  return result;
}

} // namespace trace_checker

#endif // EDGE_SWAPPING_3_LABORATORY_TRACE_CHECKER_H
