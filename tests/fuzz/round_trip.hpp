#pragma once
// Round trips: what a reader accepted, written by the matching writer and
// read again, must come back value for value (the writers print the
// shortest decimal that reads back as the same double).  Aborts, naming the
// file kind, when it does not.

#include <cstddef>

#include <gpdr/files.hpp>
#include <gpdr/io.hpp>

namespace gpdr::fuzz {

void expect_node_round_trip(const io::ReadResult<NodeSet>& read);
void expect_poly_round_trip(const io::ReadResult<PolyFile>& read);
void expect_ele_round_trip(const io::ReadResult<EleSet>& read, int vertex_base,
                           std::size_t vertex_count);
void expect_area_round_trip(const AreaSet& areas, int base);

}  // namespace gpdr::fuzz
