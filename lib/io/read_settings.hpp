#pragma once
// How the readers of .node and .poly files may read: on how many threads,
// in slices of at least how many bytes.  The public readers (gpdr/io.hpp)
// take a thread count; the functions here also take the slice size, which
// the tests set to 0 so that even a few lines are cut into many slices.

#include <cstddef>
#include <string>

#include <gpdr/diagnostics.hpp>
#include <gpdr/files.hpp>
#include <gpdr/io.hpp>

namespace gpdr::io::detail {

struct ReadSettings {
    unsigned threads = 1;
    // Slices of fewer bytes are not worth a thread: a file of less than
    // twice this is read on one.
    std::size_t min_slice_bytes = std::size_t{1} << 20;
};

ReadResult<NodeSet> read_node_with(const std::string& path, const WarningSink& warn,
                                   int default_base, const ReadSettings& settings);
ReadResult<PolyFile> read_poly_with(const std::string& path, const WarningSink& warn,
                                    int default_base, const KnownNodes* known,
                                    const ReadSettings& settings);

}  // namespace gpdr::io::detail
