// SPDX-License-Identifier: GPL-3.0-or-later
// The readings of Algorithm 4 (the helper strategy) where the paper leaves a
// choice open, as options of the paper's cycles: how long a tag lasts, which
// visits may make a helper swap, and when the cycles end. The default is the
// package's reading; laboratory/doc/traces.md quotes the sentence of the
// paper each option interprets.

#ifndef CGAL_EDGE_SWAPPING_3_HELPER_READING_H
#define CGAL_EDGE_SWAPPING_3_HELPER_READING_H

#include <string>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {

/// \ingroup PkgEdgeSwapping3Reports
/// How long a tag of Algorithm 4 lasts.
enum Tag_lifetime
{
  TAGS_UNTIL_CELL_DESTROYED, ///< a tag goes with its tetrahedron (the default)
  TAGS_CLEARED_EACH_CYCLE,   ///< every tag is cleared when a cycle begins
  /// A tag stays with the four vertices: a tetrahedron made again on them is tagged again.
  TAGS_NEVER_CLEARED
};

/// \ingroup PkgEdgeSwapping3Reports
/// Which visits may make a helper swap.
enum Helper_swap_condition
{
  /// A Delaunay facet whose two cells are untagged is passed over: a swap it
  /// would make waits for a visit of a facet of the tagged cell (the default).
  PASS_OVER_UNTAGGED_DELAUNAY_FACETS,
  /// As Algorithm 4 is written: every visit swaps a convex configuration with a tag on any of its tetrahedra.
  TAG_ON_ANY_TETRAHEDRON,
  /// A convex configuration is swapped only if one of the two cells of the visited facet is tagged.
  TAG_ON_FACET_CELLS
};

/// \ingroup PkgEdgeSwapping3Reports
/// When the paper's cycles end.
enum Cycle_ending
{
  NO_SWAP_AND_NO_NEW_TAG, ///< after a cycle with no swap and no new tag (the default)
  NO_SWAP                 ///< after a cycle with no swap, as Algorithm 3's loop is written
};

/// \ingroup PkgEdgeSwapping3Reports
/// When the facets that flips make during a cycle are visited.
enum Made_facets_visit
{
  MADE_FACETS_NEXT_CYCLE, ///< in the next cycle (the default)
  /// In the same cycle, if the cycle's order has not passed their place (the
  /// fixed and random orders: a cycle is a sweep through an order of vertex triples).
  MADE_FACETS_SAME_CYCLE
};

/// \ingroup PkgEdgeSwapping3Reports
/// One reading of Algorithm 4 (named parameter `helper_reading`; the paper's cycles only).
struct Helper_reading
{
  Tag_lifetime tag_lifetime = TAGS_UNTIL_CELL_DESTROYED;                    ///< how long a tag lasts
  Helper_swap_condition swap_condition = PASS_OVER_UNTAGGED_DELAUNAY_FACETS; ///< which visits may swap
  Cycle_ending cycle_ending = NO_SWAP_AND_NO_NEW_TAG;                        ///< when the cycles end
  Made_facets_visit made_facets = MADE_FACETS_NEXT_CYCLE;                    ///< when facets made in a cycle are visited

  /// Whether this is the package's reading, the one the work queue runs.
  bool is_default() const
  {
    return tag_lifetime == TAGS_UNTIL_CELL_DESTROYED && swap_condition == PASS_OVER_UNTAGGED_DELAUNAY_FACETS &&
           cycle_ending == NO_SWAP_AND_NO_NEW_TAG && made_facets == MADE_FACETS_NEXT_CYCLE;
  }
};

/// \ingroup PkgEdgeSwapping3Reports
/// The names of the options in files: "until-destroyed", "cleared-each-cycle" or "never-cleared".
inline const char* tag_lifetime_name(Tag_lifetime t)
{
  static const char* names[] = {"until-destroyed", "cleared-each-cycle", "never-cleared"};
  return names[t];
}
/// \ingroup PkgEdgeSwapping3Reports
/// "pass-over", "any-tetrahedron" or "facet-cells".
inline const char* helper_swap_condition_name(Helper_swap_condition c)
{
  static const char* names[] = {"pass-over", "any-tetrahedron", "facet-cells"};
  return names[c];
}
/// \ingroup PkgEdgeSwapping3Reports
/// "no-swap-no-tag" or "no-swap".
inline const char* cycle_ending_name(Cycle_ending e) { return e == NO_SWAP_AND_NO_NEW_TAG ? "no-swap-no-tag" : "no-swap"; }
/// \ingroup PkgEdgeSwapping3Reports
/// "next-cycle" or "same-cycle".
inline const char* made_facets_visit_name(Made_facets_visit m)
{
  return m == MADE_FACETS_NEXT_CYCLE ? "next-cycle" : "same-cycle";
}

/// \ingroup PkgEdgeSwapping3Reports
/// The reading's name: its option names joined by commas. The fourth is
/// written only when it is not the default ("same-cycle"), so that the names
/// of the first readings stay as they were.
inline std::string helper_reading_name(const Helper_reading& r)
{
  std::string name = std::string(tag_lifetime_name(r.tag_lifetime)) + "," +
                     helper_swap_condition_name(r.swap_condition) + "," + cycle_ending_name(r.cycle_ending);
  if(r.made_facets != MADE_FACETS_NEXT_CYCLE) name += std::string(",") + made_facets_visit_name(r.made_facets);
  return name;
}

/// \ingroup PkgEdgeSwapping3Reports
/// Every reading, the package's first.
inline std::vector<Helper_reading> all_helper_readings()
{
  std::vector<Helper_reading> all;
  for(Made_facets_visit m : {MADE_FACETS_NEXT_CYCLE, MADE_FACETS_SAME_CYCLE})
    for(Cycle_ending e : {NO_SWAP_AND_NO_NEW_TAG, NO_SWAP})
      for(Helper_swap_condition c : {PASS_OVER_UNTAGGED_DELAUNAY_FACETS, TAG_ON_ANY_TETRAHEDRON, TAG_ON_FACET_CELLS})
        for(Tag_lifetime t : {TAGS_UNTIL_CELL_DESTROYED, TAGS_CLEARED_EACH_CYCLE, TAGS_NEVER_CLEARED})
          all.push_back(Helper_reading{t, c, e, m});
  return all;
}

/// \ingroup PkgEdgeSwapping3Reports
/// The reading named `name` (as `helper_reading_name` writes it, or with
/// ",next-cycle" at the end) in `r`; false for another name.
inline bool helper_reading_from_name(const std::string& name, Helper_reading& r)
{
  for(const Helper_reading& candidate : all_helper_readings())
  {
    const std::string n = helper_reading_name(candidate);
    if(n == name || (candidate.made_facets == MADE_FACETS_NEXT_CYCLE && n + ",next-cycle" == name))
    {
      r = candidate;
      return true;
    }
  }
  return false;
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_HELPER_READING_H
