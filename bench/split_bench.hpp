// Case 10 of bench_speed (bench/split_bench.cpp): what stepping each building on its own
// between contacts could buy at most (issue 38 part 1; docs/speed.md "Buildings on their own
// steps"): per lumped sample, the steps and CPU time of the row's free run against those of
// each building simulated alone, and of the pounding run.
#pragma once

#include <string>
#include <vector>

// Runs it on the study tree src; arguments: STUDY (a path under src) [N [REPEAT [--key value
// ...]]]. Returns the exit status (2 for a bad argument).
int split_case(const std::string& src, const std::vector<std::string>& arguments);
