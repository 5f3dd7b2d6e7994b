#pragma once
// Lagged coherency of the ground motion at two stations of a row (issue 28, docs/ground.md):
// |gamma(d, f)| in [0, 1], the modulus of the cross-spectrum S_jk / sqrt(S_jj S_kk) once the
// wave-passage phase is removed, for a separation d [m] along the direction the waves travel
// and a frequency f [Hz]. Models (parameters SI, in this order):
//
//  * none: 1 (fully coherent; the row's stations differ by wave passage only).
//  * harichandran-vanmarcke-1986 (Harichandran & Vanmarcke 1986, J. Eng. Mech. 112(2):154-174):
//      |gamma| = A exp[-2 d (1 - A + alpha A) / (alpha theta)] + (1 - A) exp[-2 d (1 - A +
//      alpha A) / theta],  theta(f) = k [1 + (f / f0)^b]^(-1/2);
//    parameters A (0, 1] [-], alpha > 0 [-], k > 0 [m], f0 > 0 [Hz], b > 0 [-]; default their
//    SMART-1 event 20 fit 0.736, 0.147, 5210 m, 1.09 Hz (6.85 rad/s), 2.78.
//  * luco-wong-1986 (Luco & Wong 1986, EESD 14:891-908): |gamma| = exp[-(alpha omega d)^2],
//    omega = 2 pi f; parameter alpha > 0 [s/m] (their mu / v_s); default 2.5e-4 s/m.
//  * hao-oliveira-penzien-1989 (Hao, Oliveira & Penzien 1989, Nucl. Eng. Des. 111:293-310),
//    the longitudinal terms (a row's separation lies along the wave direction):
//      |gamma| = exp(-beta d) exp[-alpha(f) sqrt(d) f^2],  alpha(f) = a / f + b f + c,
//    alpha evaluated at f clamped to the fitted 0.05-10 Hz (0.314-62.83 rad/s);
//    parameters beta >= 0 [1/m], a [s/m^0.5], b [s^3/m^0.5], c [s^2/m^0.5] with alpha >= 0 over
//    0.05-10 Hz; default the SMART-1 event 45 values 1.109e-4, 3.583e-3, -1.811e-5, 1.177e-4
//    (docs/ground.md says where they come from and what could not be checked).
//  * abrahamson-2007-soil, abrahamson-2007-rock (Abrahamson 2007, EPRI 1015110, the horizontal
//    plane-wave coherency of soil and of rock sites, fitted on dense arrays): |gamma| =
//      [1 + (f tanh(a3 d) / (a1 fc(d)))^n1(d)]^(-1/2) [1 + (f tanh(a3 d) / a2(d))^n2]^(-1/2),
//    a1 = 1, a3 = 0.4 1/m; soil: n1 = 3, n2 = 15, a2 = 15.8 - 0.044 d [Hz], fc = 14.3 -
//    2.35 ln(d + 1) [Hz]; rock: n1 = 3.8 - 0.04 ln(d + 1) + 0.0105 (ln(d + 1) - 3.6)^2,
//    n2 = 16.4, a2 = 40 Hz, fc = 27.9 - 4.82 ln(d + 1) + 1.24 (ln(d + 1) - 3.6)^2 [Hz] (d in m);
//    d held at 300 m in a2, fc and n1 (not in tanh; the soil a2 vanishes at 359 m); no
//    parameters (docs/ground.md: the source of the coefficients and what they were checked on).
//
// A plane-wave (lagged) coherency is what remains once the delay of a single plane wave is
// removed: the cross-spectrum of stations j, k is |gamma| exp(-i 2 pi f (tau_k - tau_j)) with
// the wave-passage delays tau of [ground] apparent_velocity (wave_passage.hpp).
#include <string>
#include <vector>

namespace pound {

enum class CoherencyModel {
  none,
  harichandran_vanmarcke_1986,
  luco_wong_1986,
  hao_oliveira_penzien_1989,
  abrahamson_2007_soil,
  abrahamson_2007_rock
};

struct Coherency {
  CoherencyModel model = CoherencyModel::none;
  std::vector<double> parameters;  ///< in the model's order, SI (above)
  /// Lagged coherency |gamma(d, f)| in [0, 1] for separation d >= 0 [m], frequency f >= 0 [Hz];
  /// 1 for none and at d = 0.
  double operator()(double d, double f) const;
  std::string name() const;      ///< "none", "harichandran-vanmarcke-1986", ...
  std::string describe() const;  ///< name and parameters, one line
  /// The smallest station separation of the data the model was fitted on [m]; 0 when the
  /// model has no such floor (none, luco-wong-1986, the Abrahamson models).
  double fitted_min_separation() const;
};

/// The note for a model used at separations below its fitted range, one line without a
/// trailing newline; empty when `smallest_separation` [m] is within the range (or no model):
/// the model, its fitted range, its coherency at zero frequency gamma0 at that separation to
/// three decimals and the share sqrt(2 (1 - gamma0)) of the ground displacement it leaves
/// independent. The caller prints it (the kernels do not print).
std::string fitted_range_note(const Coherency& c, double smallest_separation);

/// The smallest distance between two of `positions` [m]; +inf for fewer than two.
double smallest_separation(const std::vector<double>& positions);

/// The model names, for messages and --help: "none, harichandran-vanmarcke-1986, ...".
std::string coherency_model_names();

/// The model `name` with `parameters` (empty: the model's defaults). Throws InputError with one
/// line naming `where` (a file:line:key or --flag text given by the caller), the offending
/// parameter and what is valid: an unknown model, a wrong count, a parameter out of range.
Coherency make_coherency(const std::string& name, const std::vector<double>& parameters,
                         const std::string& where);

}  // namespace pound
