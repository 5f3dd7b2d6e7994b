#pragma once
// A campaign's failed writes: a journal or result file that cannot be written for want of space
// (disk full, quota, file size limit: out_of_space(), core/error.hpp) stops the run as SIGTERM
// does, journal kept, exit 75, resumed once there is space; any other failure (a read-only file
// system, no permission, an I/O error) would fail again on resume, so it is an error naming the
// file, the system's reason and what the journal keeps (exit 2).
#include <exception>
#include <string>

#include "campaign/campaign_run.hpp"
#include "campaign/campaign_study.hpp"
#include "core/error.hpp"

namespace pound {

/// The first failed write of the journal in one run (master): the campaign stops as on
/// SIGTERM. Kept per run, apart from the signals' flag: a later run in the same process
/// (tests, bench_master) is not stopped by it, and a signal that came meanwhile is not lost.
struct WriteFailure {
  std::string message;   ///< the WriteError's text ("" while none failed)
  int error_number = 0;  ///< its errno
  bool happened() const { return !message.empty(); }
  /// Keeps the first failure only.
  void note(const WriteError& e);
};

/// After the master stopped on a failed journal write: counts what the journal holds (the
/// master's own count may include records that never reached the disk) into `sum`, and either
/// marks the run stopped with the reason (out of space) or throws a WriteError saying how many
/// samples the journal keeps for a resume once `out`.journal can be written.
void settle_journal_failure(const WriteFailure& failure, const CampaignStudy& st,
                            const std::string& out, CampaignSummary& sum);

/// A failure of the system while writing a file, as an exception of writing the result file
/// shows it: a WriteError, or any error while HDF5 recorded a system errno (h5::system_error).
struct SystemFailure {
  std::string reason;    ///< the exception's text, with HDF5's system reason when it has one
  int error_number = 0;  ///< the errno
};

/// The system failure behind `e`, or false when `e` is no failure of the system (a bug, bad
/// input): then the caller reports e.what() as it is.
bool system_failure(const std::exception& e, SystemFailure& out);

}  // namespace pound
