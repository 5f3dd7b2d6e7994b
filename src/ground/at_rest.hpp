#pragma once
// Generated motions under different buildings made to start and end at rest (issue 28;
// docs/ground.md, "Kinematics of a delayed generated motion"). A generated motion starts at a
// non-zero acceleration a_0 (the matching's corrections leave it there) and is baseline-corrected
// for integration from rest at its first sample; the solvers integrate each building's ground
// from rest one sample earlier (ground/ground_trace.hpp), with the rise 0 -> a_0, and a
// fractional delay's band-limited shift adds its own drift. Under one building that moves
// nothing (a building responds to ag alone); between buildings on different motions it leaves a
// relative ground velocity of up to 1e-2 m/s at 0.3 g and a relative displacement growing with
// it, 4 cm after 15 s: as large as the relative displacement the spatial variation itself
// gives. So a row's generated motions, when they differ, are each corrected here so that its
// GroundTrace ends at rest where it started, with the correction of baseline_correct
// (motion/motion_processing.hpp: a polynomial in time that vanishes at both ends, least squares
// on the displacement, zero final velocity and displacement) applied from the sample before
// the motion arrives (its last leading zero, or the rest at -dt) to the end. The acceleration
// before the arrival stays zero and the last value is kept. Recorded motions are
// never corrected here ([motion] baseline decides), nor one motion under every building (bit
// for bit the uniform input). Kernel only.
#include <vector>

#include "motion/ground_motion.hpp"

namespace pound {

/// `m` corrected so that its GroundTrace (from rest at -dt) has zero final velocity and
/// displacement [m/s, m] to round-off, its leading zeros kept.
GroundMotion ending_at_rest(const GroundMotion& m);

/// When the generated `motions` of a row (one per building or station, delayed) are not all
/// the same (bit for bit), each one ending_at_rest(); else unchanged.
void end_at_rest_where_they_differ(std::vector<GroundMotion>& motions);

}  // namespace pound
