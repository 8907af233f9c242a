// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_DEFAULT_INIT_ALLOCATOR_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_DEFAULT_INIT_ALLOCATOR_H

// An allocator whose `construct()` without arguments default-initializes
// (leaves integers uninitialized) instead of value-initializing: a
// `resize()` of a per-lattice-point array then does not write the array a
// first time, serially, before the (parallel) pass that fills every entry.

#include <memory>
#include <new>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

template <typename T, typename Base = std::allocator<T>>
class Default_init_allocator : public Base
{
  typedef std::allocator_traits<Base> Traits;

public:
  template <typename U>
  struct rebind
  {
    typedef Default_init_allocator<U, typename Traits::template rebind_alloc<U>> other;
  };

  using Base::Base;
  Default_init_allocator() = default;
  template <typename U, typename B>
  Default_init_allocator(const Default_init_allocator<U, B>& other) : Base(other)
  {}

  template <typename U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible<U>::value)
  {
    ::new(static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args)
  {
    Traits::construct(static_cast<Base&>(*this), p, std::forward<Args>(args)...);
  }
};

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_DEFAULT_INIT_ALLOCATOR_H
