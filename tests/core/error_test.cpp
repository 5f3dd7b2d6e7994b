// core/error.hpp: which failed writes a campaign takes for a full disk (a stop, resumed once
// there is space) and which for an error, and what each exception carries.
#include "core/error.hpp"

#include <gtest/gtest.h>

#include <cerrno>
#include <cstring>
#include <string>

namespace pound {
namespace {

TEST(Error, OnlyAFullDiskAQuotaAndAFileSizeLimitAreOutOfSpace) {
  for (int e : {ENOSPC, EDQUOT, EFBIG}) EXPECT_TRUE(out_of_space(e)) << std::strerror(e);
  // What freeing space does not cure: the campaign must end with an error, not "resume later".
  for (int e : {0, EROFS, EACCES, EPERM, EIO, EBADF, EISDIR, ENOENT, EINTR})
    EXPECT_FALSE(out_of_space(e)) << e << ": " << std::strerror(e);
}

TEST(Error, AWriteErrorIsBadInputWithItsMessageAndErrno) {
  try {
    throw WriteError("run.h5.journal: cannot write the campaign journal (No space left on device)",
                     ENOSPC);
  } catch (const InputError& e) {  // main() reports it as any bad input: one line, exit 2
    EXPECT_STREQ(e.what(),
                 "run.h5.journal: cannot write the campaign journal (No space left on device)");
    const auto* w = dynamic_cast<const WriteError*>(&e);
    ASSERT_NE(w, nullptr);
    EXPECT_EQ(w->error_number(), ENOSPC);
  }
  EXPECT_EQ(WriteError("x").error_number(), 0);  // unknown errno
}

TEST(Error, ANumericalFailureIsNoInputError) {
  // main() gives exit 3 to a numerical failure and 2 to bad input: they must not be confused.
  const NumericalError n("step-size underflow at t = 1.5 s");
  EXPECT_EQ(dynamic_cast<const InputError*>(static_cast<const std::exception*>(&n)), nullptr);
  EXPECT_STREQ(n.what(), "step-size underflow at t = 1.5 s");
  const InputError i("study.ini:3: key 'e': valid: e in (0, 1]");
  EXPECT_EQ(dynamic_cast<const NumericalError*>(static_cast<const std::exception*>(&i)), nullptr);
}

}  // namespace
}  // namespace pound
