// SPDX-License-Identifier: GPL-3.0-or-later
// The synthetic flow field of the two-spheres demo (the paper's Fig. 12 case,
// without a flow solver): free stream along +x at unit speed and density, a
// bow-shock-like jump a little ahead of each sphere, bent downstream away
// from the axis, and a wake of slow fluid behind each sphere. Smooth (tanh
// fronts of width 0.02) so that linear interpolation converges, but steep
// enough that the gradient indicator finds the shock and the wakes.
// Documented in doc/Edge_swapping_3/user_manual.md.

#ifndef EDGE_SWAP_FLOW_FIELD_H
#define EDGE_SWAP_FLOW_FIELD_H

#include "types.h"
#include <array>
#include <cmath>
#include <string>

namespace edge_swap {

/// The two-spheres geometry: a box around two spheres on the x axis.
struct Two_spheres
{
  std::array<double, 3> box_min{{-3, -2.5, -2.5}}, box_max{{7, 2.5, 2.5}};
  double radius = 0.5;
  std::array<double, 2> center_x{{0, 3}}; ///< centers on the flow axis (y = z = 0)
};

inline double shock_front(const Two_spheres& g, int s, const Point& p, double& r2)
{
  r2 = p.y() * p.y() + p.z() * p.z();
  const double R = g.radius;
  // Standoff 0.35 R on the axis; the front bends back as r^2 / (2 * 1.2 R).
  const double x_shock = g.center_x[s] - R - 0.35 * R + r2 / (2.4 * R);
  return 0.5 * (1 + std::tanh((p.x() - x_shock) / 0.02));
}

/// Density: 1 upstream, up to 2.5 behind each shock near the axis.
inline double flow_density(const Two_spheres& g, const Point& p)
{
  double rho = 1;
  for(int s = 0; s < 2; ++s)
  {
    double r2;
    const double jump = shock_front(g, s, p, r2);
    rho += 1.5 * jump * std::exp(-r2 / (9 * g.radius * g.radius));
  }
  return rho;
}

/// Speed: 1 upstream, slower behind each shock, slowest in the wakes.
inline double flow_speed(const Two_spheres& g, const Point& p)
{
  double u = 1;
  for(int s = 0; s < 2; ++s)
  {
    double r2;
    const double jump = shock_front(g, s, p, r2);
    const double R = g.radius;
    u -= 0.4 * jump * std::exp(-r2 / (9 * R * R));
    const double behind = p.x() - g.center_x[s];
    if(behind > 0)
    {
      const double width = R * (1 + 0.15 * behind / R);
      u -= 0.5 * std::tanh(behind / (0.1 * R)) * std::exp(-r2 / (2 * width * width)) * std::exp(-behind / (8 * R));
    }
  }
  return u;
}

/// The named synthetic fields ("flow-density", "flow-speed"); false for another name.
inline bool synthetic_field(const std::string& name, const Point& p, double& value)
{
  const Two_spheres g;
  if(name == "flow-density") value = flow_density(g, p);
  else if(name == "flow-speed") value = flow_speed(g, p);
  else return false;
  return true;
}

} // namespace edge_swap

#endif
