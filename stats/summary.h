#pragma once
// Mean, spread and range of a list of samples, as seed 004's tables report them.
#include <cstddef>
#include <span>

namespace tessref::stats {

struct Summary {
  std::size_t count = 0;
  double mean = 0.0;
  double std_dev = 0.0;  // sample standard deviation, sqrt(sum (x - mean)^2 / (n - 1))
  double min = 0.0, max = 0.0;
  // What seed 004's Table 3 prints as "std dev": sqrt(std_dev^2 + (mean / 2)^2), the spread
  // about half the mean (docs/stats.md: recovered from the table's 36 rows, none of which fits
  // the plain standard deviation, of d or of |d|, sample or population).
  double seed004_table3_spread() const;
};

// Two passes in index order over the samples (sums in double): the same bits for the same
// samples, however they were computed. An empty list gives count 0 and zeros.
Summary summarize(std::span<const double> samples);

}  // namespace tessref::stats
