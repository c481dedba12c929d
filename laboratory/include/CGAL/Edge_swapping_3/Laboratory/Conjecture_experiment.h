// SPDX-License-Identifier: GPL-3.0-or-later
// The conjecture laboratory's instance runner: an experiment (point
// families, sizes, seeds, starts, strategies, face orders) enumerated as
// instances, always in the same order (so that shards and resumed runs
// agree), each made into a case and run on all cores. Files are the
// caller's: a visitor sees each instance's case and outcome, one at a time.

#ifndef CGAL_EDGE_SWAPPING_3_LABORATORY_CONJECTURE_EXPERIMENT_H
#define CGAL_EDGE_SWAPPING_3_LABORATORY_CONJECTURE_EXPERIMENT_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Random.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Edge_swapping_3/Laboratory/Conjecture_case.h>
#include <CGAL/Edge_swapping_3/internal/facet_priority.h>
#include <CGAL/Edge_swapping_3/parameters.h>
#include <CGAL/Edge_swapping_3/point_families.h>
#include <algorithm>
#include <atomic>
#include <exception>
#include <map>
#include <memory>
#include <mutex>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>
#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

namespace CGAL {
namespace Edge_swapping_3 {

/// \ingroup PkgEdgeSwapping3Laboratory
/// One instance of an experiment.
struct Conjecture_instance
{
  std::string family;    ///< a name of `point_family_names()`, or "file:PATH"
  std::size_t size = 0;  ///< number of points (0 for a file)
  unsigned seed = 1;     ///< of the points, the placing order and the face order
  std::string start;     ///< placing | scramble:K | topcom:I (the I-th TOPCOM triangulation) | - (insertion)
  Conjecture_strategy strategy = HELPER_STRATEGY; ///< what runs
  Face_order order = RANDOM_ORDER;                ///< the face order
  Helper_reading reading;                         ///< the helper's reading of Algorithm 4

  /// The instance's name in results files: family|size|seed|start|strategy|order,
  /// and |reading when it is not the package's.
  std::string key() const
  {
    return family + "|" + std::to_string(size) + "|" + std::to_string(seed) + "|" + start + "|" +
           conjecture_strategy_name(strategy) + "|" + face_order_name(order) +
           (reading.is_default() ? std::string() : "|" + helper_reading_name(reading));
  }
};

/// \ingroup PkgEdgeSwapping3Laboratory
/// Where the face-order seed of a TOPCOM start comes from. With the set's
/// seed, every start of a point set runs the same random orders (one sweep
/// sequence, one stream of shuffles) and the same fixed priority: the runs
/// are correlated. With a seed per start, they are independent samples.
enum Order_seeds
{
  ORDER_SEED_PER_SET,  ///< the point set's seed (the default)
  ORDER_SEED_PER_START ///< `order_seed_of_start(set seed, I)` for "topcom:I"
};

/// \ingroup PkgEdgeSwapping3Laboratory
/// "per-set" or "per-start".
inline const char* order_seeds_name(Order_seeds s) { return s == ORDER_SEED_PER_START ? "per-start" : "per-set"; }

/// \ingroup PkgEdgeSwapping3Laboratory
/// The setting named `name` ("per-set", "per-start") in `s`; false for another name.
inline bool order_seeds_from_name(const std::string& name, Order_seeds& s)
{
  for(Order_seeds k : {ORDER_SEED_PER_SET, ORDER_SEED_PER_START})
    if(name == order_seeds_name(k))
    {
      s = k;
      return true;
    }
  return false;
}

/// \ingroup PkgEdgeSwapping3Laboratory
/// The face-order seed of the start "topcom:I" of the point set with seed
/// `set_seed` under `ORDER_SEED_PER_START`: the high half of
/// m(m(set_seed) + I + 1), m the SplitMix64 finalizer. Start numbers one
/// apart get unrelated seeds (not seeds one apart, whose random sweeps
/// would be related through `internal::random_sweep_seed`).
inline unsigned order_seed_of_start(unsigned set_seed, std::size_t start)
{
  return unsigned(internal::splitmix64(internal::splitmix64(set_seed) + std::uint64_t(start) + 1) >> 32);
}

/// \ingroup PkgEdgeSwapping3Laboratory
/// An experiment: every combination of its lists.
template <class Point>
struct Conjecture_experiment
{
  std::vector<std::string> families{"random-cube"};  ///< family names, and "file:PATH" for `point_files`
  std::map<std::string, std::vector<Point>> point_files; ///< the points of each "file:PATH" family
  std::vector<std::size_t> sizes{100};               ///< numbers of points of the named families
  unsigned first_seed = 1;                           ///< seeds first_seed to last_seed
  unsigned last_seed = 10;                           ///< the last seed
  std::vector<std::string> starts{"placing"};        ///< placing, scramble:K, topcom
  std::vector<Conjecture_strategy> strategies{PLAIN_SWAPS, HELPER_STRATEGY}; ///< the strategies
  std::vector<Face_order> orders{RANDOM_ORDER};      ///< the face orders
  /// The helper's readings (plain swapping and insertion run the package's). A
  /// reading that visits facets made in a cycle in it is not run in storage order.
  std::vector<Helper_reading> readings{Helper_reading()};
  std::size_t max_cycles = 1000;                     ///< the cycle limit of each run
  Order_seeds order_seeds = ORDER_SEED_PER_SET;      ///< the face-order seed of TOPCOM starts
};

/// \ingroup PkgEdgeSwapping3Laboratory
/// The points of `family` with `size` points and `seed`, in the family's own
/// order (a "file:PATH" family: the experiment's points of that file).
/// Throws `std::invalid_argument` for an unknown family.
template <class Point>
std::vector<Point> conjecture_family_points(const Conjecture_experiment<Point>& experiment, const std::string& family,
                                            std::size_t size, unsigned seed)
{
  if(family.rfind("file:", 0) == 0)
  {
    const auto it = experiment.point_files.find(family);
    if(it == experiment.point_files.end()) throw std::invalid_argument("no points for the family '" + family + "'");
    return it->second;
  }
  return make_point_family<Point>(family, size, seed);
}

/// \ingroup PkgEdgeSwapping3Laboratory
/// The instances of an experiment, and the TOPCOM triangulations they start from.
struct Conjecture_instances
{
  std::vector<Conjecture_instance> instances; ///< in the order every shard and resume sees
  /// By point set ("family|size|seed"): the triangulations of its "topcom:I" starts.
  std::map<std::string, std::vector<std::vector<std::array<std::size_t, 4>>>> topcom_cells;
  /// By point set: the number of its first triangulation in `topcom_cells`
  /// (0 when absent; a stream of triangulations holds one batch at a time).
  std::map<std::string, std::size_t> topcom_first;
};

/// \ingroup PkgEdgeSwapping3Laboratory
/// Appends to `out` the instances of `experiment` from one start of one
/// point set: each strategy other than insertion, in each face order and
/// (the helper) each reading, except same-cycle readings in storage order.
template <class Point>
void append_start_instances(const Conjecture_experiment<Point>& experiment, const std::string& family,
                            std::size_t size, unsigned seed, const std::string& start,
                            std::vector<Conjecture_instance>& out)
{
  for(Conjecture_strategy strategy : experiment.strategies)
    if(strategy != INSERTION_WITH_PLAIN_SWAPS)
      for(Face_order order : experiment.orders)
        for(const Helper_reading& reading :
            strategy == HELPER_STRATEGY ? experiment.readings : std::vector<Helper_reading>{Helper_reading()})
          if(order != STORAGE_ORDER || reading.made_facets != MADE_FACETS_SAME_CYCLE)
            out.push_back({family, size, seed, start, strategy, order, reading});
}

/// \ingroup PkgEdgeSwapping3Laboratory
/// The instances of `experiment`, always in the same order. A "topcom" start
/// becomes one instance per triangulation that `enumerate(points, set)`
/// returns (`set` names the point set, "family|size|seed"; the result is a
/// `std::vector<std::vector<std::array<std::size_t, 4>>>`, for example
/// TOPCOM's through `IO::topcom_triangulations()`); the insertion strategy
/// has one instance per point set and order, without a start.
template <class Point, class Enumerate>
Conjecture_instances conjecture_instances(const Conjecture_experiment<Point>& experiment, Enumerate enumerate)
{
  Conjecture_instances out;
  if(experiment.first_seed > experiment.last_seed) return out;
  const bool insertion = std::find(experiment.strategies.begin(), experiment.strategies.end(),
                                   INSERTION_WITH_PLAIN_SWAPS) != experiment.strategies.end();
  for(const auto& family : experiment.families)
    for(std::size_t size : family.rfind("file:", 0) == 0 ? std::vector<std::size_t>{0} : experiment.sizes)
      for(unsigned seed = experiment.first_seed;; ++seed)
      {
        const std::string set = family + "|" + std::to_string(size) + "|" + std::to_string(seed);
        for(const auto& start : experiment.starts)
        {
          std::size_t count = 1;
          if(start == "topcom")
          {
            auto& cells = out.topcom_cells[set] = enumerate(conjecture_family_points(experiment, family, size, seed), set);
            count = cells.size();
          }
          for(std::size_t t = 0; t < count; ++t)
            append_start_instances(experiment, family, size, seed,
                                   start == "topcom" ? "topcom:" + std::to_string(t) : start, out.instances);
        }
        if(insertion)
          for(Face_order order : experiment.orders)
            out.instances.push_back({family, size, seed, "-", INSERTION_WITH_PLAIN_SWAPS, order});
        if(seed == experiment.last_seed) break;
      }
  return out;
}

/// \ingroup PkgEdgeSwapping3Laboratory
/// The case of `instance`: its family's points (for placing and insertion
/// in an order drawn from the seed), its start and strategy, the
/// experiment's cycle limit, and its face-order seed (the set's, or for a
/// TOPCOM start under `ORDER_SEED_PER_START` the start's). Throws
/// `std::invalid_argument` for a bad start.
template <class Point>
Conjecture_case<Point> conjecture_case_of(const Conjecture_instance& instance,
                                          const Conjecture_experiment<Point>& experiment,
                                          const Conjecture_instances& instances)
{
  Conjecture_case<Point> c;
  c.points = conjecture_family_points(experiment, instance.family, instance.size, instance.seed);
  c.strategy = instance.strategy;
  c.order = instance.order;
  c.reading = instance.reading;
  c.seed = instance.seed;
  c.max_cycles = experiment.max_cycles;
  const std::string& start = instance.start;
  if(start.rfind("topcom:", 0) == 0)
  {
    c.start = GIVEN_CELLS_START;
    const std::string set = instance.family + "|" + std::to_string(instance.size) + "|" + std::to_string(instance.seed);
    const auto first = instances.topcom_first.find(set);
    const std::size_t index = std::stoul(start.substr(7));
    const std::size_t offset = first == instances.topcom_first.end() ? 0 : first->second;
    if(index < offset) throw std::invalid_argument("triangulation " + start + " is not held");
    if(experiment.order_seeds == ORDER_SEED_PER_START) c.seed = order_seed_of_start(instance.seed, index);
    c.cells = oriented_cells(c.points, instances.topcom_cells.at(set).at(index - offset));
    return c;
  }
  if(start == "placing" || start == "-")
  {
    c.start = start == "-" ? NO_START : PLACING_START;
    CGAL::Random r(instance.seed);
    for(std::size_t k = 0; k + 1 < c.points.size(); ++k)
      std::swap(c.points[k], c.points[k + std::size_t(r.get_int(0, int(c.points.size() - k)))]);
    return c;
  }
  if(start.rfind("scramble:", 0) == 0)
  {
    c.start = SCRAMBLED_DELAUNAY_START;
    c.scramble_flips = std::stoul(start.substr(9));
    return c;
  }
  throw std::invalid_argument("unknown start '" + start + "' (placing, scramble:K, topcom:I, -)");
}

/// \ingroup PkgEdgeSwapping3Laboratory
/// Runs the instances `todo` of `experiment` on several threads. For each,
/// in any order but one at a time, calls `visitor(instance, case, outcome)`.
/// The first error stops the run and is thrown once every thread has
/// stopped: an exception of the visitor as it is, an error of a case as a
/// `std::runtime_error` that names the instance. Returns the number of
/// threads it ran on: TBB's (CGAL_LINKED_WITH_TBB), else one.
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{visitor}
///     \cgalParamDescription{sees each instance's case and outcome}
///     \cgalParamType{a callable `void(const Conjecture_instance&, const Conjecture_case<Point>&, const Conjecture_outcome&)`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_threads}
///     \cgalParamDescription{the threads to run on}
///     \cgalParamType{`unsigned`}
///     \cgalParamDefault{0: every core (one without TBB)}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class Point, class NamedParameters = CGAL::parameters::Default_named_parameters>
unsigned run_conjecture_experiment(const std::vector<const Conjecture_instance*>& todo,
                                   const Conjecture_experiment<Point>& experiment,
                                   const Conjecture_instances& instances,
                                   const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  auto visitor = choose_parameter(get_parameter(np, CGAL::internal_np::visitor),
                                  [](const Conjecture_instance&, const Conjecture_case<Point>&,
                                     const Conjecture_outcome&) {});
  const unsigned asked = choose_parameter(get_parameter(np, internal_np::number_of_threads), 0u);
  std::mutex mutex;
  std::atomic<std::size_t> next{0};
  std::exception_ptr error;
  auto stop_with = [&](std::exception_ptr e) {
    std::lock_guard<std::mutex> lock(mutex);
    if(!error) error = e;
    next = todo.size();
  };
  auto work_on_instances = [&]() {
    for(std::size_t k; (k = next++) < todo.size();)
    {
      const Conjecture_instance& in = *todo[k];
      Conjecture_case<Point> c;
      Conjecture_outcome o;
      try
      {
        c = conjecture_case_of(in, experiment, instances);
        o = run_conjecture_case(c);
      }
      catch(const std::exception& e)
      {
        stop_with(std::make_exception_ptr(std::runtime_error(in.key() + ": " + e.what())));
        return;
      }
      std::lock_guard<std::mutex> lock(mutex);
      if(error) return;
      try
      {
        visitor(in, c, o);
      }
      catch(...)
      {
        error = std::current_exception();
        next = todo.size();
        return;
      }
    }
  };
  // A thread never lets an exception out (that would abort the program): one
  // thrown while an error is being recorded (memory exhausted) stops the run.
  std::atomic<bool> out_of_memory{false};
  auto work = [&]() noexcept {
    try
    {
      work_on_instances();
    }
    catch(...)
    {
      out_of_memory = true;
      next = todo.size();
    }
  };
  // TBB's threads, as many as asked (or every core); without TBB, this one.
#ifdef CGAL_LINKED_WITH_TBB
  const unsigned threads = asked ? asked : unsigned(tbb::this_task_arena::max_concurrency());
  tbb::task_arena arena{int(threads)};
  arena.execute([&]() { tbb::parallel_for(0u, threads, [&](unsigned) { work(); }); });
#else
  const unsigned threads = 1;
  work();
#endif
  if(error) std::rethrow_exception(error);
  if(out_of_memory) throw std::bad_alloc();
  return threads;
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_LABORATORY_CONJECTURE_EXPERIMENT_H
