#pragma once
/// @file fixed_chunks.h
/// @brief Parallel loops over fixed-size chunks for the first-order backends: the chunks depend
/// only on the length, and sums add the chunks' partials serially in chunk order, so results do
/// not depend on the number of threads (STYLE B5 rule 3).

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace linesurf::solver {

/// Elements per parallel chunk.
inline constexpr std::size_t kFixedChunk = 8192;
/// Elements per chunk of a loop whose elements are independent (nothing summed across them):
/// any split gives the same result, so smaller chunks only balance the threads better.
inline constexpr std::size_t kElementwiseChunk = 1024;

/// Runs fn(begin, end) over the chunks of `chunk` elements of [0, n), in parallel.
template <typename Fn>
void ForChunks(std::size_t n, const Fn& fn, std::size_t chunk = kFixedChunk) {
  if (n == 0) return;
  const std::size_t num_chunks = (n + chunk - 1) / chunk;
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, num_chunks, 1),
      [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t c = r.begin(); c != r.end(); ++c) {
          fn(c * chunk, std::min(n, (c + 1) * chunk));
        }
      },
      tbb::simple_partitioner{});
}

/// Sum of fn(begin, end) over the fixed chunks of [0, n), partials added in chunk order.
template <typename Fn>
double SumChunks(std::size_t n, const Fn& fn) {
  const std::size_t num_chunks = (n + kFixedChunk - 1) / kFixedChunk;
  std::vector<double> partial(num_chunks, 0.0);
  ForChunks(n, [&](std::size_t begin, std::size_t end) {
    partial[begin / kFixedChunk] = fn(begin, end);
  });
  double sum = 0.0;
  for (double p : partial) sum += p;
  return sum;
}

/// Euclidean distance of a / scale and b / scale (two vectors of one length, scale(i) the
/// divisor of element i; elements whose scale is not positive are left out), summed over fixed
/// chunks.
template <typename T, typename Scale>
inline double ChunkedDistance(const std::vector<T>& a,
                              const std::vector<T>& b,
                              const Scale& scale) {
  return std::sqrt(SumChunks(a.size(), [&](std::size_t lo, std::size_t hi) {
    double s = 0.0;
    for (std::size_t i = lo; i < hi; ++i) {
      const double divisor = scale(i);
      if (!(divisor > 0.0)) continue;
      const double d = (static_cast<double>(a[i]) - static_cast<double>(b[i])) / divisor;
      s += d * d;
    }
    return s;
  }));
}

/// Euclidean distance of two vectors of one length, summed over fixed chunks.
template <typename T>
inline double ChunkedDistance(const std::vector<T>& a, const std::vector<T>& b) {
  return ChunkedDistance(a, b, [](std::size_t) { return 1.0; });
}

}  // namespace linesurf::solver
