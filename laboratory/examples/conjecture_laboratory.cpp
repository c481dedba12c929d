// SPDX-License-Identifier: GPL-3.0-or-later
// The conjecture laboratory from C++, without the program: every point set
// of a small experiment run with plain swapping (Algorithm 3), the helper
// strategy (Algorithm 4, Conjecture 1) and insertion with plain swaps
// (Conjecture 2), in both face orders, on both cores; the first
// counterexample (a helper run that had not ended by its cycle limit) is
// shrunk to fewer points that still fail.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/edge_swapping_3.h>
#include <CGAL/Edge_swapping_3/Laboratory/Conjecture_case.h>
#include <CGAL/Edge_swapping_3/Laboratory/Conjecture_experiment.h>
#include <CGAL/Edge_swapping_3/Laboratory/shrink_conjecture_case.h>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
namespace ES = CGAL::Edge_swapping_3;

int main()
{
  ES::Conjecture_experiment<Point> experiment;
  experiment.families = {"random-integer", "cospherical"};
  experiment.sizes = {8, 30};
  experiment.first_seed = 1;
  experiment.last_seed = 20;
  experiment.starts = {"placing", "scramble:40"};
  experiment.strategies = {ES::PLAIN_SWAPS, ES::HELPER_STRATEGY, ES::INSERTION_WITH_PLAIN_SWAPS};
  experiment.orders = {ES::STORAGE_ORDER, ES::RANDOM_ORDER};

  // No TOPCOM start here: the enumerator of start triangulations is not called.
  const ES::Conjecture_instances instances =
      ES::conjecture_instances(experiment, [](const std::vector<Point>&, const std::string&) {
        return std::vector<std::vector<std::array<std::size_t, 4>>>();
      });
  std::vector<const ES::Conjecture_instance*> todo;
  for(const auto& instance : instances.instances) todo.push_back(&instance);

  std::size_t runs = 0, stuck = 0, counterexamples = 0;
  ES::Conjecture_case<Point> first_counterexample;
  ES::run_conjecture_experiment(
      todo, experiment, instances,
      CGAL::parameters::visitor([&](const ES::Conjecture_instance& instance, const ES::Conjecture_case<Point>& c,
                                    const ES::Conjecture_outcome& o) {
        ++runs; // the visitor sees one instance at a time
        stuck += c.strategy == ES::PLAIN_SWAPS && o.ending == ES::STUCK;
        if(!ES::is_counterexample(c, o)) return;
        if(counterexamples++ == 0) first_counterexample = c;
        std::cout << "counterexample: " << instance.key() << ": " << ES::conjecture_ending_name(o) << '\n';
      }));
  std::cout << runs << " runs: plain swapping stuck in " << stuck << ", counterexamples to the conjectures: "
            << counterexamples << '\n';
  if(counterexamples > 0)
  {
    const auto small = ES::shrink_conjecture_case(first_counterexample, ES::KEEP_COUNTEREXAMPLE);
    std::cout << "the first counterexample, " << first_counterexample.points.size() << " points, shrinks to "
              << small.points.size() << " points that still fail\n";
  }
  return 0;
}
