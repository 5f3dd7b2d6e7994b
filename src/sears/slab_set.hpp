#pragma once
// The colliding slabs of a damped Sears row (sears_simulation.hpp): the state of each slab's
// internal modes at the last step's end (face and centre displacements and accelerations, and
// the prediction of its faces for the next step), and when each is stepped (event stepping,
// docs/speed.md):
//   - asleep: during a run of fine steps, a slab none of whose sites carries a force at the
//     start of the coarse interval is not stepped. Its faces are known only to within
//     free_bound of their values when it fell asleep (w0): a free mode keeps R_n, so
//     |w(t) - w0| <= face_motion_bound(hc) for the whole interval. It wakes by unloaded fine
//     steps (the same recurrence the awake path applies) to the current step's start, and at
//     the end of the interval a slab still asleep takes one exact free step of hc;
//   - dormant: during a run of coarse steps, a slab whose free vibration can raise neither its
//     peak accelerations nor an overlap is not stepped. A free mode keeps R_n, so for all later
//     free motion the faces stay within swing = 2 sum R_n of their values when it went dormant
//     (dw0), and the internal accelerations within free_accel_bound(). It wakes
//     (ModalBank::advance_free over the skipped coarse steps) as soon as a bound does not
//     settle a question.
// Kernel only: no files, no printing.
#include <vector>

#include "sears/modal_bank.hpp"
#include "sears/sears_simulation.hpp"

namespace pound::sears {

class SlabSet {
 public:
  /// The slabs of `banks` (one per colliding floor); wakes and sleeps counted in `counts`.
  SlabSet(std::vector<ModalBank>& banks, SearsStepCounts& counts);

  int size() const { return static_cast<int>(banks_.size()); }
  ModalBank& bank(int k) { return banks_[k]; }
  /// Internal displacements and accelerations of slab k at the last step's end [m], [m/s^2].
  const SectionValues& disp(int k) const { return disp_[k]; }
  const SectionValues& accel(int k) const { return accel_[k]; }

  // --- Steps -------------------------------------------------------------------------------
  /// Every awake slab's face prediction for a step by recurrence `op` with end loads `begin`
  /// going to zero (ModalBank::predict), where it is not held already.
  void predict(const std::vector<EndLoads>& begin, int op);
  /// The predicted right face of slab k: its upper bound while asleep [m].
  double predicted_right_upper(int k) const {
    return asleep_[k] ? w0_[k].right + free_bound_[k] : pred_[k].right;
  }
  /// The predicted left face of slab k: its lower bound while asleep [m].
  double predicted_left_lower(int k) const {
    return asleep_[k] ? w0_[k].left - free_bound_[k] : pred_[k].left;
  }
  /// A loaded step of awake slab k by recurrence `op`, predicting for recurrence `next_op`.
  void step(int k, const EndLoads& begin, const EndLoads& end, int op, int next_op);
  /// A free coarse step of slab k.
  void step_free(int k);
  /// `count` free coarse steps of slab k at once (a stretch on the lumped solver's steps); a
  /// dormant slab skips them.
  void step_free(int k, long count);

  // --- Asleep (runs of fine steps) ---------------------------------------------------------
  bool asleep(int k) const { return asleep_[k]; }
  int asleep_count() const { return n_asleep_; }
  /// Slab k falls asleep for a coarse interval of hc [s].
  void fall_asleep(int k, double hc);
  /// Slab k sleeps through m fine steps.
  void skip(int k, long m) { slept_[k] += m; }
  /// Slab k to the start of the current step.
  void wake(int k);
  /// At the next point of the coarse grid (`ratio` fine steps to a coarse one): every slab
  /// still asleep to the interval's end.
  void finish_sleep(long ratio);
  /// The faces of slab k when it fell asleep and how far they may move [m].
  const SectionValues& asleep_faces(int k) const { return w0_[k]; }
  double asleep_bound(int k) const { return free_bound_[k]; }

  // --- Dormant (runs of coarse steps) ------------------------------------------------------
  bool dormant(int k) const { return dormant_[k]; }
  int dormant_count() const { return n_dormant_; }
  /// Dormant slab k skips a coarse step.
  void skip_dormant(int k) {
    ++dormant_steps_[k];
    ++counts_.dormant_slab_steps;
  }
  /// Whether slab k's free vibration cannot raise a peak absolute acceleration above `lowest`
  /// [m/s^2] with its floor at |a0| [m/s^2] (the bound of its last try_dormant()).
  bool peaks_bounded(int k, double a0_abs, double lowest) const {
    return a0_abs + accel_bound_[k] <= lowest;
  }
  /// Awake slab k goes dormant when its free vibration cannot raise a peak above `lowest`.
  void try_dormant(int k, double a0_abs, double lowest);
  void wake_dormant(int k);
  void wake_all_dormant();
  /// Slab k's right face now, or its upper bound while dormant [m].
  double right_face_upper(int k) const {
    return dormant_[k] ? dw0_[k].right + swing_[k] : disp_[k].right;
  }
  /// Slab k's left face now, or its lower bound while dormant [m].
  double left_face_lower(int k) const {
    return dormant_[k] ? dw0_[k].left - swing_[k] : disp_[k].left;
  }

 private:
  void take(int k) {  // the last step's result as the slab's state
    disp_[k] = bank_out_[k].disp;
    accel_[k] = bank_out_[k].accel;
  }

  std::vector<ModalBank>& banks_;
  SearsStepCounts& counts_;
  std::vector<SectionValues> disp_, accel_, pred_;
  std::vector<ModalBank::StepResult> bank_out_;
  std::vector<int> pred_op_;  // pred_ holds predict(begin) by recurrence pred_op_ - 1 (0: none)
  const EndLoads no_load_{};
  std::vector<char> asleep_;
  std::vector<long> slept_;  // fine steps skipped since the slab fell asleep
  std::vector<SectionValues> w0_;
  std::vector<double> free_bound_;
  int n_asleep_ = 0;
  std::vector<char> dormant_;
  std::vector<long> dormant_steps_;
  std::vector<SectionValues> dw0_;
  std::vector<double> swing_, accel_bound_;
  int n_dormant_ = 0;
};

}  // namespace pound::sears
