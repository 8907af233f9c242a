// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_CONCURRENT_FOR_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_CONCURRENT_FOR_H

// A loop over [0, n) that runs in parallel under Parallel_tag (with TBB) and
// sequentially otherwise, and reports progress from the calling thread only.
// Callers make every iteration write its own output slot, so the result is
// independent of the schedule: sequential and parallel runs are identical.

#include <CGAL/Boolean_isosurfacing_3/exceptions.h>

#include <CGAL/assertions.h>
#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#  include <tbb/blocked_range.h>
#  include <tbb/parallel_for.h>
#  include <tbb/parallel_invoke.h>
#  include <tbb/parallel_sort.h>
#endif

#include <algorithm>
#include <cstddef>
#include <functional>
#include <type_traits>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

template <typename ConcurrencyTag>
constexpr bool is_parallel_tag()
{
  return std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value;
}

template <typename ConcurrencyTag>
void check_concurrency_tag()
{
#ifndef CGAL_LINKED_WITH_TBB
  CGAL_static_assertion_msg(!is_parallel_tag<ConcurrencyTag>(),
                            "Parallel_tag is enabled but TBB is unavailable.");
#endif
}

/// Maps the progress of one phase, [0, 1], to a sub-interval of the whole.
/// The callback returns `false` to cancel: `report()` then throws
/// `Operation_cancelled_error`, always from the calling thread (between the
/// batches of `concurrent_for()`), never from a TBB worker.
class Progress
{
public:
  Progress() = default;
  explicit Progress(std::function<bool(double)> callback, double begin = 0, double end = 1)
    : m_callback(std::move(callback)), m_begin(begin), m_end(end)
  {}

  void report(double fraction) const
  {
    if(m_callback && !m_callback(m_begin + (m_end - m_begin) * std::min(1.0, std::max(0.0, fraction))))
      throw Operation_cancelled_error("cancelled by the callback");
  }

  /// The progress of the part [a, b] of this phase.
  Progress part(double a, double b) const
  {
    Progress p;
    p.m_callback = m_callback;
    p.m_begin = m_begin + (m_end - m_begin) * a;
    p.m_end = m_begin + (m_end - m_begin) * b;
    return p;
  }

  bool active() const { return static_cast<bool>(m_callback); }

private:
  std::function<bool(double)> m_callback;
  double m_begin = 0, m_end = 1;
};

/// Calls `body(i)` for every i in [0, n).  With a progress callback the
/// range is cut into batches and progress is reported between them, from
/// the calling thread.
template <typename ConcurrencyTag, typename Body>
void concurrent_for(std::size_t n, const Body& body, const Progress& progress = Progress())
{
  check_concurrency_tag<ConcurrencyTag>();
  const std::size_t batches = progress.active() ? std::min<std::size_t>(n, 32) : (n > 0 ? 1 : 0);
  for(std::size_t b = 0; b < batches; ++b)
  {
    const std::size_t first = n * b / batches, last = n * (b + 1) / batches;
#ifdef CGAL_LINKED_WITH_TBB
    if constexpr(is_parallel_tag<ConcurrencyTag>())
    {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(first, last),
                        [&body](const tbb::blocked_range<std::size_t>& r) {
                          for(std::size_t i = r.begin(); i != r.end(); ++i)
                            body(i);
                        });
    }
    else
#endif
    {
      for(std::size_t i = first; i < last; ++i)
        body(i);
    }
    progress.report(double(b + 1) / double(batches));
  }
}

/// Calls `body(first, last)` for consecutive blocks [first, last) of
/// [0, n), `block` indices each (the last one shorter): `concurrent_for()`
/// over blocks, for loops whose iterations are too small to schedule one by
/// one or that keep scratch buffers per block.
template <typename ConcurrencyTag, typename Body>
void concurrent_for_blocks(std::size_t n, std::size_t block, const Body& body)
{
  concurrent_for<ConcurrencyTag>((n + block - 1) / block, [&](std::size_t b) {
    body(b * block, (std::min)(n, (b + 1) * block));
  });
}

/// Sorts [first, last) by `<`, with TBB's parallel sort under Parallel_tag.
/// Equal elements may end up in either order: give a total order (an index
/// as the last key) where the result must not depend on the schedule.
template <typename ConcurrencyTag, typename RandomAccessIterator>
void concurrent_sort(RandomAccessIterator first, RandomAccessIterator last)
{
  check_concurrency_tag<ConcurrencyTag>();
#ifdef CGAL_LINKED_WITH_TBB
  if constexpr(is_parallel_tag<ConcurrencyTag>())
  {
    tbb::parallel_sort(first, last);
    return;
  }
#endif
  std::sort(first, last);
}

/// Calls `first()` and `second()`, two independent tasks: at once under
/// Parallel_tag (with TBB), one after the other otherwise.
template <typename ConcurrencyTag, typename First, typename Second>
void concurrent_invoke(const First& first, const Second& second)
{
  check_concurrency_tag<ConcurrencyTag>();
#ifdef CGAL_LINKED_WITH_TBB
  if constexpr(is_parallel_tag<ConcurrencyTag>())
  {
    tbb::parallel_invoke(first, second);
    return;
  }
#endif
  first();
  second();
}

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_CONCURRENT_FOR_H
