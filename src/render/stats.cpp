// Percentiles and the rolling timer window; see stats.h for the conventions.
#include "render/stats.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace planet {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

double percentile(std::vector<double> values, double p) {
    if (!(p >= 0.0 && p <= 100.0)) throw std::invalid_argument("percentile: p must be in [0, 100]");
    std::erase_if(values, [](double v) { return std::isnan(v); });
    if (values.empty()) return kNaN;
    std::sort(values.begin(), values.end());
    // Rank on 0 … n-1, as numpy's "linear" method (Hyndman & Fan type 7).
    const double rank = p / 100.0 * static_cast<double>(values.size() - 1);
    const auto lo = static_cast<std::size_t>(std::floor(rank));
    const std::size_t hi = std::min(lo + 1, values.size() - 1);
    const double t = rank - static_cast<double>(lo);
    return values[lo] + t * (values[hi] - values[lo]);
}

RollingStats::RollingStats(std::size_t capacity) {
    if (capacity == 0) throw std::invalid_argument("RollingStats: capacity must be at least 1");
    ring_.assign(capacity, 0.0);
    scratch_.reserve(capacity);
}

std::size_t RollingStats::indexOf(std::size_t age) const {
    const std::size_t oldest = (next_ + ring_.size() - count_) % ring_.size();
    return (oldest + age) % ring_.size();
}

void RollingStats::push(double value) {
    if (std::isnan(value)) return;
    ring_[next_] = value;
    next_ = (next_ + 1) % ring_.size();
    count_ = std::min(count_ + 1, ring_.size());
}

double RollingStats::min() const {
    if (count_ == 0) return kNaN;
    double m = ring_[indexOf(0)];
    for (std::size_t i = 1; i < count_; ++i) m = std::min(m, ring_[indexOf(i)]);
    return m;
}

double RollingStats::max() const {
    if (count_ == 0) return kNaN;
    double m = ring_[indexOf(0)];
    for (std::size_t i = 1; i < count_; ++i) m = std::max(m, ring_[indexOf(i)]);
    return m;
}

double RollingStats::mean() const {
    if (count_ == 0) return kNaN;
    double sum = 0.0;
    for (std::size_t i = 0; i < count_; ++i) sum += ring_[indexOf(i)];
    return sum / static_cast<double>(count_);
}

double RollingStats::median() const {
    if (count_ == 0) return kNaN;
    scratch_.clear();  // keeps the capacity reserved in the constructor
    for (std::size_t i = 0; i < count_; ++i) scratch_.push_back(ring_[indexOf(i)]);
    const auto mid = scratch_.begin() + static_cast<std::ptrdiff_t>(count_ / 2);
    std::nth_element(scratch_.begin(), mid, scratch_.end());
    if (count_ % 2 == 1) return *mid;
    const double below = *std::max_element(scratch_.begin(), mid);  // lower middle
    return 0.5 * (below + *mid);
}

double RollingStats::last() const {
    if (count_ == 0) return kNaN;
    return ring_[(next_ + ring_.size() - 1) % ring_.size()];
}

std::vector<double> RollingStats::history() const {
    std::vector<double> out;
    out.reserve(count_);
    for (std::size_t i = 0; i < count_; ++i) out.push_back(ring_[indexOf(i)]);
    return out;
}

void RollingStats::clear() {
    next_ = 0;
    count_ = 0;
}

}  // namespace planet
