#pragma once
// The damped Sears contact layout of a building row: which floors are bars, their modal banks,
// the law of each contact site and the step's contact compliance S (see sears_simulation.hpp).
// At a slab-to-slab site both slabs are bars. At a slab-to-column site (issue 36;
// docs/contact-geometry.md) only the striking slab is a bar; the struck side is the
// ContactSite's weighted point on the neighbour's floors, without internal modes (the thesis'
// "columns as point springs", 9.1), and the columns' stiffness k_col acts in series with the
// law (SlabContactLaw::series_compliance_m_per_N).
#include <Eigen/Dense>
#include <vector>

#include "sears/modal_bank.hpp"
#include "sears/sears_simulation.hpp"
#include "sears/slab_contact_law.hpp"

namespace pound::sears {

/// One colliding floor: a bar whose rigid-body mode is floor DOF `dof`.
struct CollidingFloor {
  int building = 0;     ///< 0-based
  int floor = 0;        ///< 1-based
  int dof = 0;          ///< global floor DOF
  int site_left = -1;   ///< contact site at the slab's left end (x = 0), -1 when none
  int site_right = -1;  ///< contact site at the slab's right end (x = l), -1 when none
};

struct RowContactLayout {
  std::vector<CollidingFloor> floors;
  std::vector<ModalBank> banks;  ///< one per colliding floor
  /// Per site: index into floors of the left building's slab; -1 where the left side is a
  /// struck column point (no bar).
  std::vector<int> site_left_floor;
  std::vector<int> site_right_floor;  ///< per site: the right building's slab, or -1 (a column)
  std::vector<SlabContactLaw> laws;   ///< per site
};

/// The slab of floor j (0-based) of building b.
Slab floor_slab(const BuildingRow& row, const SearsRowModel& model, int b, int j);

/// The law of site s: flat (Th. 8.1-8.2) k_L = 1 / (1/k_A,L + 1/k_A,R) at a slab site; at a
/// column site the striking slab's k_A = D E A / l in series with k_col (the column takes the
/// place of the struck slab's bar). Hertz: the model's k, or Th. 7.2 from the faces' radii and
/// the two buildings' materials (a column: its building's slab material), in series with k_col
/// at a column site.
SlabContactLaw site_law(const BuildingRow& row, const SearsRowModel& model,
                        const ContactSite& site);

/// Laws and floors without banks (step-size independent).
RowContactLayout make_layout(const BuildingRow& row, const AssembledRow& a,
                             const SearsRowModel& model);

/// Builds the banks for step dt.
void build_banks(RowContactLayout& layout, const BuildingRow& row, const SearsRowModel& model,
                 double dt);

/// The modal part of the compliance for the banks' recurrence `level` (ModalBank::add_step):
/// delta_s changes by -sum_t S(s,t) F_t [m/N].
Eigen::MatrixXd modal_compliance(const RowContactLayout& layout, int level);

}  // namespace pound::sears
