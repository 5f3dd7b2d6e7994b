#include "sears/slab_set.hpp"

namespace pound::sears {

SlabSet::SlabSet(std::vector<ModalBank>& banks, SearsStepCounts& counts)
    : banks_(banks), counts_(counts) {
  const std::size_t nf = banks.size();
  disp_.resize(nf);
  accel_.resize(nf);
  pred_.resize(nf);
  bank_out_.resize(nf);
  pred_op_.assign(nf, 0);
  asleep_.assign(nf, 0);
  slept_.assign(nf, 0);
  w0_.resize(nf);
  free_bound_.assign(nf, 0.0);
  dormant_.assign(nf, 0);
  dormant_steps_.assign(nf, 0);
  dw0_.resize(nf);
  swing_.assign(nf, 0.0);
  accel_bound_.assign(nf, 0.0);
}

void SlabSet::predict(const std::vector<EndLoads>& begin, int op) {
  for (int k = 0; k < size(); ++k)
    if (!asleep_[k] && pred_op_[k] != op + 1) {
      pred_[k] = banks_[k].predict(begin[k], op);
      pred_op_[k] = op + 1;
    }
}

void SlabSet::step(int k, const EndLoads& begin, const EndLoads& end, int op, int next_op) {
  banks_[k].step(begin, end, bank_out_[k], op, next_op);
  take(k);
  pred_[k] = bank_out_[k].next_pred;
  pred_op_[k] = next_op + 1;
}

void SlabSet::step_free(int k) {
  banks_[k].step_free(bank_out_[k]);
  take(k);
  pred_op_[k] = 0;
}

void SlabSet::step_free(int k, long count) {
  if (dormant_[k]) {
    dormant_steps_[k] += count;
    counts_.dormant_slab_steps += count;
    return;
  }
  banks_[k].advance_free(count, bank_out_[k]);
  take(k);
  pred_op_[k] = 0;
}

void SlabSet::fall_asleep(int k, double hc) {
  asleep_[k] = 1;
  slept_[k] = 0;
  w0_[k] = disp_[k];
  free_bound_[k] = banks_[k].face_motion_bound(hc);
  ++n_asleep_;
  ++counts_.slab_sleeps;
}

void SlabSet::wake(int k) {
  for (long j = 0; j < slept_[k]; ++j) banks_[k].step(no_load_, no_load_, bank_out_[k]);
  if (slept_[k] > 0) {
    take(k);
    pred_[k] = bank_out_[k].next_pred;
    pred_op_[k] = 1;
  }
  asleep_[k] = 0;
  slept_[k] = 0;
  --n_asleep_;
  ++counts_.slab_wakes;
}

void SlabSet::finish_sleep(long ratio) {
  for (int k = 0; k < size(); ++k) {
    if (!asleep_[k]) continue;
    if (slept_[k] == ratio) {
      banks_[k].step_free(bank_out_[k]);
    } else {
      for (long j = 0; j < slept_[k]; ++j) banks_[k].step(no_load_, no_load_, bank_out_[k]);
    }
    take(k);
    pred_op_[k] = 0;
    asleep_[k] = 0;
    slept_[k] = 0;
  }
  n_asleep_ = 0;
}

void SlabSet::try_dormant(int k, double a0_abs, double lowest) {
  accel_bound_[k] = banks_[k].free_accel_bound();
  if (!(a0_abs + accel_bound_[k] <= lowest)) return;
  dormant_[k] = 1;
  dormant_steps_[k] = 0;
  dw0_[k] = disp_[k];
  swing_[k] = 2.0 * banks_[k].free_face_bound();
  ++n_dormant_;
  ++counts_.dormant_runs;
}

void SlabSet::wake_dormant(int k) {
  banks_[k].advance_free(dormant_steps_[k], bank_out_[k]);
  take(k);
  pred_op_[k] = 0;
  dormant_[k] = 0;
  dormant_steps_[k] = 0;
  --n_dormant_;
  ++counts_.dormant_wakes;
}

void SlabSet::wake_all_dormant() {
  for (int k = 0; k < size(); ++k)
    if (dormant_[k]) wake_dormant(k);
}

}  // namespace pound::sears
