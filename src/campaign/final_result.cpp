#include "campaign/final_result.hpp"

#include <unistd.h>

#include <cstdio>

#include "campaign/write_failure.hpp"
#include "io/atomic_file.hpp"

namespace pound {

std::string write_final_result(const CampaignStudy& st, const CampaignRunOptions& opt, RunInfo info,
                               CampaignSummary& sum) {
  try {
    char host[256] = {};
    ::gethostname(host, sizeof host - 1);
    info.host = host;
    AtomicPath out(opt.out);
    write_result_file(out.temp(), st, opt.out + ".journal", info);
    out.commit();
    std::remove((opt.out + ".journal").c_str());
    return "";
  } catch (const std::exception& e) {
    SystemFailure failure;
    if (!system_failure(e, failure)) return e.what();
    if (!out_of_space(failure.error_number))
      return failure.reason + "; the journal " + opt.out +
             ".journal keeps every sample: run again with --resume once " + opt.out +
             " can be written";
    sum.interrupted = true;
    sum.stop_reason = failure.reason;
    return "";
  }
}

}  // namespace pound
