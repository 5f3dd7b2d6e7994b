#include "campaign/write_failure.hpp"

#include "campaign/journal.hpp"
#include "campaign/sample_schedule.hpp"
#include "io/h5.hpp"

namespace pound {
namespace {

// The samples a journal holds.
void count_journal(const CampaignStudy& st, const std::string& path, CampaignSummary& sum) {
  sum.done = sum.failed = 0;
  SampleSchedule held(st.range_lo, st.range_hi);
  try {
    for_each_record(path, st, [&](const SampleOutcome& o) {
      if (held.mark_done(o.id)) {
        ++sum.done;
        if (o.status != SampleStatus::ok) ++sum.failed;
      }
    });
  } catch (const InputError&) {  // no journal (it could not be created)
  }
}

}  // namespace

void WriteFailure::note(const WriteError& e) {
  if (happened()) return;
  message = e.what();
  error_number = e.error_number();
}

void settle_journal_failure(const WriteFailure& failure, const CampaignStudy& st,
                            const std::string& out, CampaignSummary& sum) {
  sum.total = st.range_size();
  count_journal(st, out + ".journal", sum);
  if (!out_of_space(failure.error_number)) {
    std::string text = failure.message;
    if (sum.done > 0)
      text += "; the journal keeps " + std::to_string(sum.done) + " of " +
              std::to_string(sum.total) + " samples: run again with --resume once " + out +
              ".journal can be written";
    throw WriteError(text, failure.error_number);
  }
  sum.interrupted = true;
  sum.stop_reason = failure.message;
}

bool system_failure(const std::exception& e, SystemFailure& out) {
  const auto* write = dynamic_cast<const WriteError*>(&e);
  const bool system = write || !h5::system_error().empty();
  if (!system) return false;
  out.reason = !h5::system_error().empty() && !write
                   ? std::string(e.what()) + " (" + h5::system_error() + ")"
                   : e.what();
  out.error_number =
      write && write->error_number() != 0 ? write->error_number() : h5::system_errno();
  return true;
}

}  // namespace pound
