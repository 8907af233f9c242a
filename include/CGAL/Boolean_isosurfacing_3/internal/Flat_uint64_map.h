// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_FLAT_UINT64_MAP_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_FLAT_UINT64_MAP_H

// A hash map from 64-bit keys (all but the largest value) to small values,
// open addressing with linear probing in one array of (key, value) slots, at
// most half full.  The contouring's lattice-point values, visited cubes and
// edge vertices are looked up about ten times a cube; in
// `std::unordered_map` each lookup follows a bucket pointer to a node
// allocated on its own, here it reads one slot (usually one cache line).
// No erase, no iteration: the callers only insert and find, so the order in
// which keys were hashed can never reach an output.  (Boost's
// unordered_flat_map would do; it needs Boost 1.81, Debian 12 has 1.74.)

#include <CGAL/assertions.h>

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

template <typename Value>
class Flat_uint64_map
{
public:
  /// The one key that cannot be stored: it marks an empty slot.
  static constexpr std::uint64_t empty_key = ~std::uint64_t(0);

  explicit Flat_uint64_map(std::size_t expected_size = 0) { reserve(expected_size); }

  /// Room for `n` keys without growing.
  void reserve(std::size_t n)
  {
    std::size_t capacity = 16;
    while(capacity < 2 * n)
      capacity *= 2;
    if(capacity > m_slots.size())
      rehash(capacity);
  }

  std::size_t size() const { return m_size; }

  /// The number of slots; it changes when an insertion grows the map, which
  /// moves every value (the pointers `insert()` returned are then stale).
  std::size_t capacity() const { return m_slots.size(); }

  /// The value of `key`, or null.
  const Value* find(std::uint64_t key) const
  {
    for(std::size_t i = slot_of(key);; i = (i + 1) & m_mask)
    {
      const Slot& s = m_slots[i];
      if(s.first == key)
        return &s.second;
      if(s.first == empty_key)
        return nullptr;
    }
  }

  bool contains(std::uint64_t key) const { return find(key) != nullptr; }

  /// Inserts (key, value) unless `key` is there: the stored value, and
  /// whether it was inserted (as `std::unordered_map::emplace`).
  std::pair<Value*, bool> insert(std::uint64_t key, const Value& value)
  {
    CGAL_precondition(key != empty_key);
    if(2 * (m_size + 1) > m_slots.size())
      rehash(2 * m_slots.size());
    for(std::size_t i = slot_of(key);; i = (i + 1) & m_mask)
    {
      Slot& s = m_slots[i];
      if(s.first == key)
        return {&s.second, false};
      if(s.first == empty_key)
      {
        s = Slot(key, value);
        ++m_size;
        return {&s.second, true};
      }
    }
  }

private:
  typedef std::pair<std::uint64_t, Value> Slot;

  // A multiplicative mix, then the high bits: lattice keys differ mostly in
  // their low bits of each packed coordinate.
  std::size_t slot_of(std::uint64_t key) const
  {
    key ^= key >> 29;
    key *= 0xbf58476d1ce4e5b9ull;
    key ^= key >> 32;
    return std::size_t(key) & m_mask;
  }

  void rehash(std::size_t capacity)
  {
    std::vector<Slot> old(capacity, Slot(empty_key, Value()));
    old.swap(m_slots);
    m_mask = capacity - 1;
    m_size = 0;
    for(const Slot& s : old)
      if(s.first != empty_key)
        insert(s.first, s.second);
  }

  std::vector<Slot> m_slots;
  std::size_t m_mask = 0;
  std::size_t m_size = 0;
};

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_FLAT_UINT64_MAP_H
