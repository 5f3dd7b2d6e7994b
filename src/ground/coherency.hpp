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
#include <string>
#include <vector>

namespace pound {

enum class CoherencyModel {
  none,
  harichandran_vanmarcke_1986,
  luco_wong_1986,
  hao_oliveira_penzien_1989
};

struct Coherency {
  CoherencyModel model = CoherencyModel::none;
  std::vector<double> parameters;  ///< in the model's order, SI (above)
  /// Lagged coherency |gamma(d, f)| in [0, 1] for separation d >= 0 [m], frequency f >= 0 [Hz];
  /// 1 for none and at d = 0.
  double operator()(double d, double f) const;
  std::string name() const;      ///< "none", "harichandran-vanmarcke-1986", ...
  std::string describe() const;  ///< name and parameters, one line
};

/// The model names, for messages and --help: "none, harichandran-vanmarcke-1986, ...".
std::string coherency_model_names();

/// The model `name` with `parameters` (empty: the model's defaults). Throws InputError with one
/// line naming `where` (a file:line:key or --flag text given by the caller), the offending
/// parameter and what is valid: an unknown model, a wrong count, a parameter out of range.
Coherency make_coherency(const std::string& name, const std::vector<double>& parameters,
                         const std::string& where);

}  // namespace pound
