// Case 6 of bench_speed (bench/collapse_bench.cpp): the imk storey law against the bilinear one
// on the default study's samples, and the time the stop at collapse saves (issue 23).
#pragma once

#include <string>
#include <vector>

// Runs it on the study tree src; arguments: [N [REPEAT [imk|bilinear|both [--key value ...]]]].
// Returns the exit status (2 for a bad argument).
int collapse_case(const std::string& src, const std::vector<std::string>& arguments);
