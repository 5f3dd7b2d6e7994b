#include "sampling/distribution.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "io/options.hpp"
#include "sampling/normal.hpp"

namespace pound {
namespace {

const char* kForms =
    "valid: a number, fixed(x), uniform(a, b), normal(mean, sd[, lo, hi]), "
    "lognormal(median, beta[, lo, hi]), discrete(value: weight, ...)";

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : s) {
    if (c == sep) {
      out.push_back(trim(cur));
      cur.clear();
    } else {
      cur += c;
    }
  }
  out.push_back(trim(cur));
  return out;
}

}  // namespace

Distribution Distribution::parse(const std::string& raw, const std::string& where) {
  Distribution d;
  d.text_ = trim(raw);
  const std::string& t = d.text_;
  const auto open = t.find('(');
  if (open == std::string::npos) {
    d.kind_ = DistributionKind::fixed;
    d.p1_ = parse_number(t, where + " (" + kForms + ")");
    return d;
  }
  if (t.back() != ')') throw InputError(where + ": '" + t + "' lacks a closing ')'; " + kForms);
  const std::string name = trim(t.substr(0, open));
  const std::string inner = t.substr(open + 1, t.size() - open - 2);
  const auto args = split(inner, ',');
  auto num = [&](std::size_t i) { return parse_number(args[i], where + " in '" + t + "'"); };
  auto need = [&](std::size_t a, std::size_t b) {
    if (args.size() != a && args.size() != b)
      throw InputError(where + ": '" + t + "' has " + std::to_string(args.size()) + " arguments; " +
                       kForms);
  };
  if (name == "fixed") {
    need(1, 1);
    d.kind_ = DistributionKind::fixed;
    d.p1_ = num(0);
  } else if (name == "uniform") {
    need(2, 2);
    d.kind_ = DistributionKind::uniform;
    d.p1_ = num(0);
    d.p2_ = num(1);
    if (!(d.p2_ >= d.p1_)) throw InputError(where + ": uniform(a, b) needs a <= b");
  } else if (name == "normal" || name == "lognormal") {
    need(2, 4);
    d.kind_ = name == "normal" ? DistributionKind::normal : DistributionKind::lognormal;
    const double a = num(0), s = num(1);
    if (!(s > 0))
      throw InputError(where + ": the standard deviation (beta) must be > 0 in '" + t + "'");
    if (d.kind_ == DistributionKind::lognormal && !(a > 0))
      throw InputError(where + ": the median of a lognormal must be > 0 in '" + t + "'");
    d.p1_ = d.kind_ == DistributionKind::lognormal ? std::log(a) : a;
    d.p2_ = s;
    if (args.size() == 4) {
      d.truncated_ = true;
      d.lo_ = num(2);
      d.hi_ = num(3);
      if (!(d.hi_ > d.lo_)) throw InputError(where + ": truncation needs lo < hi in '" + t + "'");
      if (d.kind_ == DistributionKind::lognormal && !(d.lo_ > 0))
        throw InputError(where + ": lognormal truncation bounds must be > 0 in '" + t + "'");
      auto z = [&](double x) {
        return ((d.kind_ == DistributionKind::lognormal ? std::log(x) : x) - d.p1_) / d.p2_;
      };
      d.plo_ = normal_cdf(z(d.lo_));
      d.phi_ = normal_cdf(z(d.hi_));
      if (!(d.phi_ > d.plo_))
        throw InputError(where + ": the truncation interval has no probability in '" + t + "'");
    }
  } else if (name == "discrete") {
    d.kind_ = DistributionKind::discrete;
    double total = 0;
    for (const auto& item : args) {
      const auto colon = item.rfind(':');
      std::string label = trim(item), w = "1";
      if (colon != std::string::npos) {
        label = trim(item.substr(0, colon));
        w = trim(item.substr(colon + 1));
      }
      const double weight = parse_number(w, where + " weight of '" + label + "'");
      if (label.empty() || !(weight > 0))
        throw InputError(where + ": discrete outcomes need a value and a weight > 0 in '" + t +
                         "'");
      d.labels_.push_back(label);
      total += weight;
      d.cumulative_.push_back(total);
    }
    for (double& c : d.cumulative_) c /= total;
  } else {
    throw InputError(where + ": unknown distribution '" + name + "'; " + kForms);
  }
  return d;
}

std::size_t Distribution::index(double u) const {
  const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), u);
  return std::min<std::size_t>(it - cumulative_.begin(), cumulative_.size() - 1);
}

const std::string& Distribution::label(double u) const {
  return labels_.at(index(u));
}

double Distribution::value(double u) const {
  switch (kind_) {
    case DistributionKind::fixed:
      return p1_;
    case DistributionKind::uniform:
      return p1_ + u * (p2_ - p1_);
    case DistributionKind::normal:
    case DistributionKind::lognormal: {
      const double p = truncated_ ? plo_ + u * (phi_ - plo_) : u;
      double x = p1_ + p2_ * normal_quantile(p);
      if (kind_ == DistributionKind::lognormal) x = std::exp(x);
      if (truncated_) x = std::min(std::max(x, lo_), hi_);  // round-off at the bounds
      return x;
    }
    case DistributionKind::discrete:
      return parse_number(label(u), "discrete value");
  }
  return std::numeric_limits<double>::quiet_NaN();
}

double Distribution::lower() const {
  switch (kind_) {
    case DistributionKind::fixed:
      return p1_;
    case DistributionKind::uniform:
      return p1_;
    case DistributionKind::normal:
      return truncated_ ? lo_ : -INFINITY;
    case DistributionKind::lognormal:
      return truncated_ ? lo_ : 0.0;
    case DistributionKind::discrete: {
      double m = INFINITY;
      for (const auto& l : labels_) m = std::min(m, parse_number(l, "discrete value"));
      return m;
    }
  }
  return 0;
}

double Distribution::upper() const {
  switch (kind_) {
    case DistributionKind::fixed:
      return p1_;
    case DistributionKind::uniform:
      return p2_;
    case DistributionKind::normal:
    case DistributionKind::lognormal:
      return truncated_ ? hi_ : INFINITY;
    case DistributionKind::discrete: {
      double m = -INFINITY;
      for (const auto& l : labels_) m = std::max(m, parse_number(l, "discrete value"));
      return m;
    }
  }
  return 0;
}

}  // namespace pound
