#pragma once
// A libFuzzer mutator that edits JSON as JSON, so that mutations reach what lies behind the parser
// (a glTF's accessors and nodes, a bake index's fields) instead of breaking its syntax nearly
// every time.

#include <cstddef>
#include <cstdint>

namespace luxel::fuzz {

/// When the bytes are JSON: one structural edit of them (a value replaced by a boundary number,
/// another type or a copy of another value; an element removed or duplicated; a string mutated
/// by libFuzzer), written back into `data`; returns the new size. 0 when the bytes are not JSON or
/// the edit does not fit in `max_size`.
size_t mutate_json(uint8_t* data, size_t size, size_t max_size, unsigned seed);

}  // namespace luxel::fuzz
