// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_TBISO_SLAB_PIPELINE_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_TBISO_SLAB_PIPELINE_H

// The slab pipeline of extract_boolean_isosurface_by_slabs(): read (in slab
// order), evaluate (in parallel), weld (in slab order).

#include <CGAL/Boolean_isosurfacing_3/internal/Concurrent_for.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Tbiso/Tbiso_chunk.h>

#ifdef CGAL_LINKED_WITH_TBB
#  include <tbb/parallel_pipeline.h>
#endif

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

// The cube layers [k_begin, k_end) of slab s, and the vertex layers
// [first_layer, last_layer] its fields are read for (one ghost layer on each
// side: the apex of a neighbouring tetrahedron may lie there).
struct Slab_window
{
  Slab_window(std::size_t s, std::size_t slab, std::size_t layers)
    : k_begin(s * slab), k_end((std::min)(layers, s * slab + slab)),
      first_layer(k_begin > 0 ? k_begin - 1 : 0), last_layer((std::min)(layers, k_end + 1))
  {}
  std::size_t k_begin, k_end, first_layer, last_layer;
};

// A slab in flight: its number, its field values, its polygons.
struct Tbiso_slab_slot
{
  std::size_t slab = 0;
  std::vector<double> values;
  Tbiso_chunk chunk;
};

// Runs read(slot), evaluate(slot), weld(slot) for every slab in order; under
// a parallel tag as a TBB pipeline with `slots.size()` slabs in flight (the
// evaluations in parallel, reading and welding in slab order).
template <typename ConcurrencyTag, typename Read, typename Evaluate, typename Weld>
void run_slab_pipeline(std::size_t number_of_slabs, std::vector<Tbiso_slab_slot>& slots, const Read& read,
                       const Evaluate& evaluate, const Weld& weld)
{
  typedef Tbiso_slab_slot Slot;
  const std::size_t slabs_in_flight = slots.size();
  (void)slabs_in_flight; // only the TBB pipeline reads it
#ifdef CGAL_LINKED_WITH_TBB
  if constexpr(is_parallel_tag<ConcurrencyTag>())
  {
    std::size_t next_slab = 0;
    tbb::parallel_pipeline(
        slabs_in_flight,
        tbb::make_filter<void, Slot*>(tbb::filter_mode::serial_in_order,
                                      [&](tbb::flow_control& control) -> Slot* {
                                        if(next_slab == number_of_slabs)
                                        {
                                          control.stop();
                                          return nullptr;
                                        }
                                        // Tokens finish in order, so slab s - slabs_in_flight is done.
                                        Slot& slot = slots[next_slab % slabs_in_flight];
                                        slot.slab = next_slab++;
                                        read(slot);
                                        return &slot;
                                      }) &
            tbb::make_filter<Slot*, Slot*>(tbb::filter_mode::parallel,
                                           [&](Slot* slot) {
                                             evaluate(*slot);
                                             return slot;
                                           }) &
            tbb::make_filter<Slot*, void>(tbb::filter_mode::serial_in_order, [&](Slot* slot) { weld(*slot); }));
  }
  else
#endif
  {
    for(std::size_t s = 0; s < number_of_slabs; ++s)
    {
      Slot& slot = slots[0];
      slot.slab = s;
      read(slot);
      evaluate(slot);
      weld(slot);
    }
  }
}

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_TBISO_SLAB_PIPELINE_H
