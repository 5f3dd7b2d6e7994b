#pragma once
// The subcommands of the `pound` program. Each parses its options, calls the library and
// reports; argv[0] is the subcommand name.
namespace pound::app {
int run_impact(int argc, const char* const* argv);
int run_simulate(int argc, const char* const* argv);
int run_motion(int argc, const char* const* argv);
int run_campaign(int argc, const char* const* argv);
int run_merge(int argc, const char* const* argv);
int run_fragility(int argc, const char* const* argv);
int run_summary(int argc, const char* const* argv);
int run_risk(int argc, const char* const* argv);
int run_hysteresis(int argc, const char* const* argv);
/// pound motion generate (argv[0] "generate"), called by run_motion.
int run_motion_generate(int argc, const char* const* argv);
}  // namespace pound::app
