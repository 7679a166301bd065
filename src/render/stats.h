// Small statistics helpers for frame timings.
//
// percentile() matches numpy.percentile's default ("linear") method: sort the
// samples, place p on the rank axis 0 … n-1 and interpolate linearly between the
// two closest ranks. RollingStats keeps the last N samples of one timer (a
// GPU pass, the CPU frame) in a fixed ring and answers min / median / max /
// mean over that window for the overlay and `planet bench`.
//
// Conventions: NaN samples are ignored (a timer query that has no result yet),
// and every statistic of an empty set is NaN, never 0, so "no data" cannot be
// mistaken for "free".
#pragma once

#include <cstddef>
#include <vector>

namespace planet {

// p-th percentile of values, p in [0, 100] (std::invalid_argument otherwise).
// Linear interpolation between closest ranks, as numpy's default. NaN values
// are skipped; no (non-NaN) values gives NaN. Takes the vector by value
// because it sorts it.
double percentile(std::vector<double> values, double p);

// The last `capacity` samples of one quantity. push() never allocates after
// construction; the order statistics use a scratch buffer that is also
// allocated once, so a RollingStats is not safe to share between threads.
class RollingStats {
public:
    explicit RollingStats(std::size_t capacity = 240);  // capacity >= 1

    void push(double value);  // NaN is ignored; the oldest sample drops out when full
    std::size_t size() const { return count_; }
    std::size_t capacity() const { return ring_.size(); }

    double min() const;     // NaN when empty
    double median() const;  // mean of the two middle samples for an even count
    double max() const;
    double mean() const;
    double last() const;    // most recent sample

    std::vector<double> history() const;  // oldest → newest
    void clear();

private:
    std::size_t indexOf(std::size_t age) const;  // age 0 = oldest

    std::vector<double> ring_;
    std::size_t next_ = 0;   // slot the next push writes
    std::size_t count_ = 0;
    mutable std::vector<double> scratch_;  // reserved to capacity, for median()
};

}  // namespace planet
