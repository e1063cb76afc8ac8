// The rows of an inflow buffer's driven water in the pressure equation (`[[inflow]] pressure`, case_config.hpp):
//  * "solved" (default): like the water's, with the divergence and compression source of eq. (9) / the mixed source.
//  * "harmonic": without a source, so the buffer's pressure solves
//        <lap p>_i = 0   (plus the known terms of its walls and free-surface neighbours),
//    the pressure of a uniform flow (the divergence of the momentum equation, lap p = -rho div (u . grad u), vanishes
//    for u uniform), continued from the water in front of the buffer; the mirrored walls around it keep their
//    hydrostatic Neumann condition (wall_mirror.hpp) and lose their velocity term. Still water in front of a buffer
//    then continues into it at its hydrostatic pressure. The buffer's velocity is prescribed, so its rows constrain
//    nothing of its own; they only give the water in front of it the pressure behind it.
//
// Why (docs/waterfall.md, "The inflow buffer's pressure"): with the source, the buffer's rows read the gap its upstream
// layer opens behind it (a new layer is made when a whole l0 fits) and the wall it leaves behind as expansion. The
// liquid system clamps that to p >= 0; the one equation, with no free surface in a closed box, kept it as tension:
// -10 to -40 kPa in a 5 cm buffer whose hydrostatic pressure is 0.5 kPa at most, pulling on the water leaving it.
#pragma once

#include <vector>

#include "case/case_config.hpp"
#include "mps/open_boundaries.hpp"
#include "mps/particles.hpp"

namespace mistfall {

// Per particle: 1 for the driven water of an inflow with pressure = "harmonic" (a row without a source); empty when
// no inflow is harmonic (PressureProblem::sourceless).
template <int D>
std::vector<char> harmonicInflowRows(const Particles<D>& p, const CaseConfig& c) {
  std::vector<char> rows;
  for (const Inflow& in : c.inflows) {
    if (in.pressure != Inflow::Pressure::Harmonic) continue;
    rows.resize(p.size(), 0);
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.kind[i] == ParticleKind::Inflow && insideBox<D>(p.position[i], in.box)) rows[i] = 1;
  }
  return rows;
}

}  // namespace mistfall
