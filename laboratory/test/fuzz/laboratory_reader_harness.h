// SPDX-License-Identifier: GPL-3.0-or-later
// The harness of each of the laboratory's readers (laboratory_readers.h),
// shared by its libFuzzer targets and its mutation test: read `data` as the
// file `name`, and when it is accepted, go on as the program does (run a small
// case, summarise results, check a trace). The outcome is either accepted or
// rejected with the error's message. Any other exception, a crash or a hang is
// a defect.

#ifndef EDGE_SWAPPING_3_LABORATORY_FUZZ_READER_HARNESS_H
#define EDGE_SWAPPING_3_LABORATORY_FUZZ_READER_HARNESS_H

#include "laboratory_readers.h"
#include "trace_checker.h"
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_3.h>
#include <CGAL/Edge_swapping_3/Laboratory/IO/conjecture_json.h>
#include <CGAL/Edge_swapping_3/Laboratory/IO/streamed_results.h>
#include <CGAL/Edge_swapping_3/Laboratory/IO/topcom.h>
#include <CGAL/Edge_swapping_3/Laboratory/Conjecture_case.h>
#include <CGAL/Edge_swapping_3/triangulation_from_cells.h>
#include <algorithm>
#include <sstream>
#include <string>
#include <string_view>

namespace lab_fuzz {

namespace ES = CGAL::Edge_swapping_3;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;

// The points the TOPCOM harness triangulates: a cube's corners and centre.
inline std::vector<Point> topcom_points()
{
  std::vector<Point> p;
  for(int k = 0; k < 8; ++k) p.emplace_back(k & 1, (k >> 1) & 1, (k >> 2) & 1);
  p.emplace_back(0.5, 0.5, 0.5);
  return p;
}

/// Runs `reader` on `data`.
inline Outcome run(Reader reader, std::string_view data)
{
  Outcome o;
  const std::string name = file_name(reader);
  try
  {
    switch(reader)
    {
    case Reader::topcom:
    {
      std::istringstream in{std::string(data)};
      const auto points = topcom_points();
      for(const auto& cells : CGAL::Edge_swapping_3::IO::read_topcom_triangulations(in))
      {
        CGAL::Triangulation_3<K> tr;
        std::vector<CGAL::Triangulation_3<K>::Vertex_handle> vertices;
        o.message = ES::build_triangulation_from_cells(tr, points, ES::oriented_cells(points, cells),
                                                                          vertices);
        if(!o.message.empty()) { o.message = name + ": " + o.message; return o; }
      }
      o.accepted = true;
      break;
    }
    case Reader::case_json:
    {
      const auto j = nlohmann::json::parse(data.begin(), data.end(), nullptr, false);
      if(j.is_discarded()) { o.message = name + ": not JSON"; break; }
      ES::Conjecture_case<Point> c = ES::IO::conjecture_case_from_json<Point>(j, name);
      // Run small cases, briefly: the drivers see what the file set up.
      if(c.points.size() <= 40 && (c.start != ES::SCRAMBLED_DELAUNAY_START || c.scramble_flips <= 100))
      {
        c.max_cycles = std::min<std::size_t>(c.max_cycles, 20);
        const auto outcome = ES::run_conjecture_case(c);
        if(outcome.bad_start) { o.message = name + ": " + ES::conjecture_ending_name(outcome); break; }
        if(!outcome.valid) throw std::logic_error("a case ended on an invalid triangulation");
      }
      o.accepted = true;
      break;
    }
    case Reader::streamed:
    {
      std::istringstream in{std::string(data)};
      std::vector<ES::IO::Streamed_tally> tallies;
      std::size_t keep = 0;
      ES::IO::read_streamed_results(name, in, [&](const ES::IO::Streamed_tally& t) { tallies.push_back(t); }, keep);
      if(keep > data.size()) throw std::logic_error("a resume would keep more than the file");
      std::ostringstream summary;
      ES::IO::print_streamed_summary(name, tallies, summary);
      o.accepted = true;
      break;
    }
    case Reader::trace:
    {
      // The independent checker: a trace is confirmed, or a line is named.
      std::istringstream in{std::string(data)};
      const auto result = trace_checker::check_trace(in);
      if(result.ok) o.accepted = true;
      else o.message = name + ": " + result.error;
      break;
    }
    case Reader::results:
    {
      const auto lines = ES::IO::read_results_text(name, std::string(data));
      std::ostringstream summary;
      ES::IO::print_results_summary(name, lines, summary);
      o.accepted = true;
      break;
    }
    }
  }
  catch(const CGAL::Edge_swapping_3::IO::Input_error& e)
  {
    o.message = e.what();
  }
  catch(const std::invalid_argument& e)
  {
    o.message = e.what();
  }
  return o;
}

} // namespace lab_fuzz

#endif
