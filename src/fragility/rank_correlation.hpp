#pragma once
// Rank correlations for the sensitivity of the pounding amplification to the sampled
// parameters (Iman & Conover 1980; Saltelli et al. 2004, "Sensitivity analysis in practice",
// section 5.2): Spearman's rho is Pearson's correlation of the ranks; the partial rank
// correlation coefficient (PRCC) of x_j with y is the correlation of the residuals of rank(x_j)
// and rank(y) after least-squares regression (with intercept) on the ranks of the other
// parameters, so it removes the part of the association carried by them.
#include <cstddef>
#include <vector>

namespace pound {

/// Ranks 1..n, ties sharing their average rank.
std::vector<double> ranks(const std::vector<double>& x);
/// Pearson's correlation; NaN when either variable is constant or n < 2.
double pearson(const std::vector<double>& x, const std::vector<double>& y);
/// Spearman's rank correlation.
double spearman(const std::vector<double>& x, const std::vector<double>& y);
/// PRCC of columns[j] with y given the other columns (each a variable over the same samples).
/// NaN when it is undefined (constant residuals, fewer samples than variables + 2).
double partial_rank_correlation(const std::vector<std::vector<double>>& columns,
                                const std::vector<double>& y, std::size_t j);

}  // namespace pound
