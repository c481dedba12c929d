// SPDX-License-Identifier: GPL-3.0-or-later
// The two-spheres case of the paper's Fig. 12 (flow past two spheres), as
// the package's demonstration domain: its geometry, and a synthetic flow
// field on it (no flow solver): free stream along +x at unit speed and
// density, a bow-shock-like jump a little ahead of each sphere, bent
// downstream away from the axis, and a wake of slow fluid behind each
// sphere. Smooth (tanh fronts of width 0.02) so that linear interpolation
// converges, but steep enough that the gradient indicator finds the shock
// and the wakes. Documented in doc/Edge_swapping_3/user_manual.md; meshed
// by make_two_spheres_mesh.h.

#ifndef CGAL_EDGE_SWAPPING_3_TWO_SPHERES_DOMAIN_H
#define CGAL_EDGE_SWAPPING_3_TWO_SPHERES_DOMAIN_H

#include <CGAL/number_utils.h>
#include <array>
#include <cmath>
#include <string>

namespace CGAL {
namespace Edge_swapping_3 {

/// \ingroup PkgEdgeSwapping3Domains
/// The two-spheres geometry: a box around two spheres on the x axis.
struct Two_spheres
{
  std::array<double, 3> box_min{{-3, -2.5, -2.5}}; ///< the box's lowest corner
  std::array<double, 3> box_max{{7, 2.5, 2.5}};    ///< the box's highest corner
  double radius = 0.5;                             ///< of both spheres
  std::array<double, 2> center_x{{0, 3}};          ///< centers on the flow axis (y = z = 0)

  /// The region of a point: 0 outside the box, 1 in the flow region, 2 and 3
  /// inside the first and second sphere.
  template <class Point>
  int region(const Point& p) const
  {
    const double c[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    for(int k = 0; k < 3; ++k)
      if(c[k] < box_min[k] || c[k] > box_max[k]) return 0;
    for(int s = 0; s < 2; ++s)
    {
      const double dx = c[0] - center_x[s];
      if(dx * dx + c[1] * c[1] + c[2] * c[2] < radius * radius) return 2 + s;
    }
    return 1;
  }
};

namespace internal {

// The shock's jump (0 ahead, 1 behind) of sphere `s` at (x, r^2 = y^2 + z^2).
inline double shock_front(const Two_spheres& g, int s, double x, double r2)
{
  const double R = g.radius;
  // Standoff 0.35 R on the axis; the front bends back as r^2 / (2 * 1.2 R).
  const double x_shock = g.center_x[s] - R - 0.35 * R + r2 / (2.4 * R);
  return 0.5 * (1 + std::tanh((x - x_shock) / 0.02));
}

} // namespace internal

/// \ingroup PkgEdgeSwapping3Domains
/// The synthetic density at `p`: 1 upstream, up to 2.5 behind each shock near the axis.
template <class Point>
double flow_density(const Two_spheres& g, const Point& p)
{
  const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y()), z = CGAL::to_double(p.z());
  const double r2 = y * y + z * z;
  double rho = 1;
  for(int s = 0; s < 2; ++s) rho += 1.5 * internal::shock_front(g, s, x, r2) * std::exp(-r2 / (9 * g.radius * g.radius));
  return rho;
}

/// \ingroup PkgEdgeSwapping3Domains
/// The synthetic speed at `p`: 1 upstream, slower behind each shock, slowest in the wakes.
template <class Point>
double flow_speed(const Two_spheres& g, const Point& p)
{
  const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y()), z = CGAL::to_double(p.z());
  const double r2 = y * y + z * z, R = g.radius;
  double u = 1;
  for(int s = 0; s < 2; ++s)
  {
    u -= 0.4 * internal::shock_front(g, s, x, r2) * std::exp(-r2 / (9 * R * R));
    const double behind = x - g.center_x[s];
    if(behind > 0)
    {
      const double width = R * (1 + 0.15 * behind / R);
      u -= 0.5 * std::tanh(behind / (0.1 * R)) * std::exp(-r2 / (2 * width * width)) * std::exp(-behind / (8 * R));
    }
  }
  return u;
}

/// \ingroup PkgEdgeSwapping3Domains
/// The value at `p` of the synthetic field `name` ("flow-density" or
/// "flow-speed") of the default `Two_spheres`, in `value`; false for another name.
template <class Point>
bool two_spheres_flow_field(const std::string& name, const Point& p, double& value)
{
  const Two_spheres g;
  if(name == "flow-density") value = flow_density(g, p);
  else if(name == "flow-speed") value = flow_speed(g, p);
  else return false;
  return true;
}

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_TWO_SPHERES_DOMAIN_H
