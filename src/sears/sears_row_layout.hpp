#pragma once
// The damped Sears contact layout of a building row: which floors are bars, their modal banks,
// the law of each contact site and the step's contact compliance S (see sears_simulation.hpp).
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
  std::vector<ModalBank> banks;       ///< one per colliding floor
  std::vector<int> site_left_floor;   ///< per site: index into floors of the left building's floor
  std::vector<int> site_right_floor;  ///< per site: the right building's floor
  std::vector<SlabContactLaw> laws;   ///< per site
};

/// The slab of floor j (0-based) of building b.
Slab floor_slab(const BuildingRow& row, const SearsRowModel& model, int b, int j);

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
