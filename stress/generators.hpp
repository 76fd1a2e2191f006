#pragma once
// The generator of each family (internal to the stress library). Each fills in the canvas, grid,
// kind and geometry of a case whose family, seed and index are already set, drawing only from
// `rng`, the case's own stream.
#include "stress/rng.hpp"
#include "stress/stress_case.hpp"

namespace scantrace::stress::detail {

void generate_random(Rng& rng, StressCase& c);
void generate_sliver(Rng& rng, StressCase& c);
void generate_near_collinear(Rng& rng, StressCase& c);
void generate_huge(Rng& rng, StressCase& c);
void generate_subpixel(Rng& rng, StressCase& c);
void generate_near_horizontal(Rng& rng, StressCase& c);
void generate_near_vertical(Rng& rng, StressCase& c);
void generate_on_lattice(Rng& rng, StressCase& c, double offset);  // centres (0), half-way (0.5)
void generate_long_span(Rng& rng, StressCase& c);
void generate_mesh(Rng& rng, StressCase& c);

// Vertex colours: mostly uniform in [0, 1], sometimes a pure 0 or 1 channel, so that the steepest
// gradients (a full channel swing across a sliver) are part of the mix.
Color random_color(Rng& rng);

}  // namespace scantrace::stress::detail
