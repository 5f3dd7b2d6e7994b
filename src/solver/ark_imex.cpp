#include "solver/ark_imex.hpp"

#include <algorithm>

#include "solver/row_dynamics.hpp"
#include "structure/building_row.hpp"

namespace pound {

namespace {

// Kennedy & Carpenter (2003), ARK5(4)8L[2]SA: the paper's rational coefficients (as SUNDIALS'
// ARKode tabulates them), checked by tests/solver/ark_imex_test.cpp (order conditions). a_i2 = 0
// for i >= 4 in both tableaux.
Ark548 make_ark548() {
  Ark548 t;
  auto& e = t.ae;
  auto& d = t.ai;
  const double g = 41.0 / 200.0;
  t.gamma = g;
  t.c = {0.0,
         41.0 / 100.0,
         2935347310677.0 / 11292855782101.0,
         1426016391358.0 / 7196633302097.0,
         92.0 / 100.0,
         24.0 / 100.0,
         3.0 / 5.0,
         1.0};
  // Explicit tableau.
  e[1][0] = 41.0 / 100.0;
  e[2][0] = 367902744464.0 / 2072280473677.0;
  e[2][1] = 677623207551.0 / 8224143866563.0;
  e[3][0] = 1268023523408.0 / 10340822734521.0;
  e[3][2] = 1029933939417.0 / 13636558850479.0;
  e[4][0] = 14463281900351.0 / 6315353703477.0;
  e[4][2] = 66114435211212.0 / 5879490589093.0;
  e[4][3] = -54053170152839.0 / 4284798021562.0;
  e[5][0] = 14090043504691.0 / 34967701212078.0;
  e[5][2] = 15191511035443.0 / 11219624916014.0;
  e[5][3] = -18461159152457.0 / 12425892160975.0;
  e[5][4] = -281667163811.0 / 9011619295870.0;
  e[6][0] = 19230459214898.0 / 13134317526959.0;
  e[6][2] = 21275331358303.0 / 2942455364971.0;
  e[6][3] = -38145345988419.0 / 4862620318723.0;
  e[6][4] = -1.0 / 8.0;
  e[6][5] = -1.0 / 8.0;
  e[7][0] = -19977161125411.0 / 11928030595625.0;
  e[7][2] = -40795976796054.0 / 6384907823539.0;
  e[7][3] = 177454434618887.0 / 12078138498510.0;
  e[7][4] = 782672205425.0 / 8267701900261.0;
  e[7][5] = -69563011059811.0 / 9646580694205.0;
  e[7][6] = 7356628210526.0 / 4942186776405.0;
  // ESDIRK (explicit first stage, diagonal gamma, stiffly accurate: its last row is b).
  d[1][0] = g;
  d[2][0] = 41.0 / 400.0;
  d[2][1] = -567603406766.0 / 11931857230679.0;
  d[3][0] = 683785636431.0 / 9252920307686.0;
  d[3][2] = -110385047103.0 / 1367015193373.0;
  d[4][0] = 3016520224154.0 / 10081342136671.0;
  d[4][2] = 30586259806659.0 / 12414158314087.0;
  d[4][3] = -22760509404356.0 / 11113319521817.0;
  d[5][0] = 218866479029.0 / 1489978393911.0;
  d[5][2] = 638256894668.0 / 5436446318841.0;
  d[5][3] = -1179710474555.0 / 5321154724896.0;
  d[5][4] = -60928119172.0 / 8023461067671.0;
  d[6][0] = 1020004230633.0 / 5715676835656.0;
  d[6][2] = 25762820946817.0 / 25263940353407.0;
  d[6][3] = -2161375909145.0 / 9755907335909.0;
  d[6][4] = -211217309593.0 / 5846859502534.0;
  d[6][5] = -4269925059573.0 / 7827059040749.0;
  t.b = {-872700587467.0 / 9133579230613.0,
         0.0,
         0.0,
         22348218063261.0 / 9555858737531.0,
         -1143369518992.0 / 8141816002931.0,
         -39379526789629.0 / 19018526304540.0,
         32727382324388.0 / 42900044865799.0,
         g};
  for (int j = 0; j < 7; ++j) d[7][j] = t.b[j];
  for (int i = 1; i < 8; ++i) d[i][i] = g;
  t.bh = {-975461918565.0 / 9796059967033.0,
          0.0,
          0.0,
          78070527104295.0 / 32432590147079.0,
          -548382580838.0 / 3424219808633.0,
          -33438840321285.0 / 15594753105479.0,
          3629800801594.0 / 4656183773603.0,
          4035322873751.0 / 18575991585200.0};
  return t;
}

}  // namespace

const Ark548& Ark548::get() {
  static const Ark548 t = make_ark548();
  return t;
}

ImplicitSet stiff_base_dashpots(const AssembledRow& row, const RowDynamics& dyn, double h_max,
                                double from) {
  ImplicitSet set;
  if (row.base_damping.empty()) return set;
  const auto& qs = dyn.quasi_static();
  const int n = row.dofs();
  double fastest = 0.0;  // [1/s]
  for (int d = row.floors; d < n; ++d) {
    const double im = row.inv_mass(d);
    if (im == 0.0 || !(row.base_damping[d] > 0.0) || std::count(qs.begin(), qs.end(), d) > 0)
      continue;
    set.index.push_back(n + d);
    set.lambda.push_back(row.base_damping[d] * im);
    fastest = std::max(fastest, set.lambda.back());
  }
  if (!(fastest * h_max >= std::max(from, kDormandPrinceBound))) set = ImplicitSet{};
  return set;
}

namespace detail {

void ark_stage(int i, double h, const Eigen::VectorXd& y0, const ImplicitSet& set, ArkImexWork& w) {
  const Ark548& a = Ark548::get();
  const Eigen::Index n = y0.size();
  double* out = w.tmp.data();
  const double* y = y0.data();
  for (Eigen::Index k = 0; k < n; ++k) out[k] = y[k];
  for (int j = 0; j < i; ++j) {
    const double c = h * a.ae[i][j];
    if (c == 0.0) continue;
    const double* f = w.F[j].data();
    for (Eigen::Index k = 0; k < n; ++k) out[k] += c * f[k];
  }
  // The implicit entries: F_E = F - F_I there, so their sum gains h (ai - ae) F_I; then
  // Y = R + h gamma f_I(Y) = R - h gamma lambda Y.
  const double hg = h * a.gamma;
  for (std::size_t m = 0; m < set.index.size(); ++m) {
    const auto k = static_cast<Eigen::Index>(m);
    double r = out[set.index[m]];
    for (int j = 0; j < i; ++j) r += h * (a.ai[i][j] - a.ae[i][j]) * w.FI[j](k);
    const double yk = r / (1.0 + hg * set.lambda[m]);
    out[set.index[m]] = yk;
    w.FI[i](k) = -set.lambda[m] * yk;
  }
}

void ark_finish(double h, const Eigen::VectorXd& y0, const ImplicitSet& set, const ArkImexWork& w,
                Eigen::VectorXd& y1, Eigen::VectorXd& err) {
  const Ark548& a = Ark548::get();
  y1 = y0;
  err.setZero();
  for (int j = 0; j < Ark548::s; ++j) {
    if (a.b[j] != 0.0) y1.noalias() += (h * a.b[j]) * w.F[j];
    const double e = a.b[j] - a.bh[j];
    if (e != 0.0) err.noalias() += (h * e) * w.F[j];
  }
  // The stiff entries' estimate filtered by (I - h gamma J_I)^-1 (Hairer & Wanner II, IV.8,
  // eq. (8.20)): their errors are damped by the L-stable ESDIRK, not propagated.
  for (std::size_t m = 0; m < set.index.size(); ++m)
    err(set.index[m]) /= 1.0 + h * a.gamma * set.lambda[m];
}

}  // namespace detail
}  // namespace pound
