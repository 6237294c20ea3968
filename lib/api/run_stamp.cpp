// The run stamp of a run's output files (see run_stamp.hpp).

#include "api/run_stamp.hpp"

#include <fmt/format.h>

#include "io/content_hash.hpp"

namespace gpdr::api {

std::string run_stamp(std::string_view command, std::uint64_t input_hash, std::uint64_t vertices,
                      std::uint64_t triangles) {
    std::uint64_t h = io::hash_bytes(command);
    h = io::hash_number(input_hash, h);
    h = io::hash_number(vertices, h);
    h = io::hash_number(triangles, h);
    return fmt::format("{:016x}", h);
}

}  // namespace gpdr::api
