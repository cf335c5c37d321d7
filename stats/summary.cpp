#include "stats/summary.h"

#include <algorithm>
#include <cmath>

namespace tessref::stats {

double Summary::seed004_table3_spread() const {
  return std::sqrt(std_dev * std_dev + 0.25 * mean * mean);
}

Summary summarize(std::span<const double> x) {
  Summary s;
  s.count = x.size();
  if (x.empty()) return s;
  double sum = 0.0;
  s.min = s.max = x[0];
  for (double v : x) {
    sum += v;
    s.min = std::min(s.min, v);
    s.max = std::max(s.max, v);
  }
  s.mean = sum / double(x.size());
  if (x.size() > 1) {
    double squares = 0.0;
    for (double v : x) squares += (v - s.mean) * (v - s.mean);
    s.std_dev = std::sqrt(squares / double(x.size() - 1));
  }
  return s;
}

}  // namespace tessref::stats
