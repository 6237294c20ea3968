#pragma once
// Reading and writing Triangle 1.6's files (.node, .poly, .ele, .area,
// .edge, .neigh, .off, .v.node, .v.edge), following
// docs/file-formats.md.
//
// Readers throw gpdr::InputError(file, line, reason) on anything malformed
// and report harmless oddities (non-consecutive ids, a segment with equal
// endpoints) through the WarningSink.  Indices are stored 0-based; each
// reader also returns the numbering base (0 or 1) it saw.
//
// Writers write into an OutputTransaction: every file goes to a temporary
// name in its target folder and is renamed into place only by commit(), so a
// failed run leaves neither truncated files nor clobbered earlier results.
// Write failures throw gpdr::OutputError naming the file.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <gpdr/diagnostics.hpp>
#include <gpdr/files.hpp>

namespace gpdr::io {

// ---------------------------------------------------------------- reading

template <class T>
struct ReadResult {
    T data;
    int base = 1;  // numbering base seen in the file: the index of its first entry (0 or 1)
    // A hash of the bytes read (a .poly's and those of the .node it takes
    // its vertices from), for the run stamp of the output files.
    std::uint64_t content_hash = 0;
};

// A .node file.  The first vertex's index (0 or 1) fixes `base`, which the
// caller passes to the readers of the run's other files.  When the file has
// no vertices, or its first index is neither 0 nor 1 (Triangle then keeps
// its default), `base` is `default_base` (1, or 0 for -z).  With `threads`
// above 1 a large regular file's vertex lines are parsed on that many
// threads; the values, errors and warnings are those of one thread.
ReadResult<NodeSet> read_node(const std::string& path, const WarningSink& warn,
                              int default_base = 1, unsigned threads = 1);

// The vertices of a .node its caller has read already: their count, the
// base and the content hash read_node() gave.
struct KnownNodes {
    std::size_t count = 0;
    int base = 1;
    std::uint64_t content_hash = 0;
};

// A .poly file.  When its vertex count is 0 the vertices come from the .node
// file of the same base name (box.poly -> box.node), which this reader loads
// into data.nodes (data.nodes_from_node_file is then true); `base` is then the
// base of that .node file.  With `known`, that .node is not read again (it
// may be a pipe, which can be read only once): data.nodes stays empty, and
// the base and hash are known's.  Segment endpoints are validated against
// the vertices and the base.  `threads` as for read_node (the vertex list;
// the rest of the file is read on one thread).
ReadResult<PolyFile> read_poly(const std::string& path, const WarningSink& warn,
                               int default_base = 1, const KnownNodes* known = nullptr,
                               unsigned threads = 1);

// An .ele file of a mesh whose vertices (vertex_count of them) number from
// `base`.  Corners out of [base, base + vertex_count) are an InputError.
// The returned base is the index of the file's first triangle.
ReadResult<EleSet> read_ele(const std::string& path, int base, std::size_t vertex_count,
                            const WarningSink& warn);

// An .area file for triangle_count triangles (the .ele's count; a different
// count is an InputError).  A triangle with no value gets -1 (no bound).
ReadResult<AreaSet> read_area(const std::string& path, int base, std::size_t triangle_count,
                              const WarningSink& warn);

// An .edge file: endpoints validated against the vertices.
ReadResult<EdgeSet> read_edge(const std::string& path, int base, std::size_t vertex_count,
                              const WarningSink& warn);

// A .neigh file for triangle_count triangles; -1 reads as NeighbourSet::none.
ReadResult<NeighbourSet> read_neigh(const std::string& path, int base, std::size_t triangle_count,
                                    const WarningSink& warn);

// Edges of a Voronoi diagram (.v.edge): a finite edge joins two Voronoi
// vertices; a ray starts at one and runs off in a direction.
struct VoronoiEdgeSet {
    static constexpr std::uint32_t ray = 0xffffffffu;  // second endpoint of a ray, written -1
    std::vector<std::uint32_t> endpoints;  // 2 per edge, 0-based; second is `ray` for rays
    std::vector<double> directions;        // 2 per edge (dx, dy); 0, 0 for finite edges

    std::size_t size() const noexcept { return endpoints.size() / 2; }
};

// A .v.edge file whose .v.node has vertex_count vertices.
ReadResult<VoronoiEdgeSet> read_voronoi_edge(const std::string& path, int base,
                                             std::size_t vertex_count, const WarningSink& warn);

// ---------------------------------------------------------------- writing

// A set of output files written together.  write_*() below add files to it;
// commit() renames them all into place, in the order they were added.  If a
// transaction is destroyed without commit() (an exception unwound past it),
// its temporary files are removed and no target file is touched.
class OutputTransaction {
public:
    OutputTransaction();
    ~OutputTransaction();
    OutputTransaction(const OutputTransaction&) = delete;
    OutputTransaction& operator=(const OutputTransaction&) = delete;

    // Renames every temporary file onto its target name.  Throws OutputError
    // if a rename fails (the files not yet renamed are removed).
    void commit();

    // The target paths, in the order they were added.
    const std::vector<std::string>& files() const noexcept;

    class File;  // one output file being written (internal)
    // Starts a new file whose final name is `path`; throws OutputError if the
    // temporary cannot be created.  Used by the write_*() functions.
    File& begin_file(const std::string& path);

private:
    void sync_folders() const noexcept;

    std::vector<std::unique_ptr<File>> files_;
    std::vector<std::string> paths_;
    bool committed_ = false;
};

// Removes every temporary file that an OutputTransaction of this process
// has made and not yet renamed or removed.  Async-signal-safe: a program's
// handler for SIGINT, SIGTERM or SIGHUP calls it before dying, so that a
// killed run leaves no hidden temporary behind.
void remove_temporary_files() noexcept;

class FormatThreads;  // threads that format pieces of a file's lines (internal)

// What every writer needs besides the data.
struct WriteFormat {
    int base = 1;         // number entries from 0 or 1
    bool markers = true;  // false (-B): write no boundary markers
    // The command that made the files, e.g. "gpdr -pq box.poly"; every file
    // ends with the line "# Generated by <command>", followed by
    // " (run <stamp>)" when `stamp` is not empty.
    std::string command;
    std::string stamp = {};
    // Threads shared by the writers of one output stage (write_outputs),
    // which format a large file's lines in pieces, written in order: the
    // bytes do not change.  Null: each file is formatted by its writer.
    FormatThreads* threads = nullptr;
};

void write_node(OutputTransaction& out, const std::string& path, const NodeSet& nodes,
                const WriteFormat& format);

// Writes the vertices inline, unless poly.nodes_from_node_file: then the
// vertex section is the header "0 2 <#attributes> <markers>" (Triangle's
// output .poly) with the counts taken from poly.nodes.attribute_count and
// poly.nodes.has_markers() (its vertices are then not used and may be left
// out).  Regions are written only when there are some, as Triangle does.
void write_poly(OutputTransaction& out, const std::string& path, const PolyFile& poly,
                const WriteFormat& format);

void write_ele(OutputTransaction& out, const std::string& path, const EleSet& triangles,
               const WriteFormat& format);

// Triangles produced one at a time, for writing a mesh without first
// copying it into an EleSet (the copy would cost 12 bytes per triangle at
// the moment memory use peaks).  next() is called exactly `count` times, in
// order, and fills corners_per_triangle 0-based corners and attribute_count
// attributes of the next triangle.
struct EleSource {
    std::size_t count = 0;
    std::uint32_t corners_per_triangle = 3;
    std::uint32_t attribute_count = 0;
    std::function<void(std::uint32_t* corners, double* attributes)> next;
    // Optional: fills the corners and attributes of triangles first to
    // first + n - 1, like n calls of next() from there, without touching
    // next()'s place; callable from several threads at once.  With it a
    // large file's triangles are read on the threads that format them.
    std::function<void(std::size_t first, std::size_t n, std::uint32_t* corners,
                       double* attributes)>
        read = {};
};
void write_ele(OutputTransaction& out, const std::string& path, const EleSource& triangles,
               const WriteFormat& format);

void write_area(OutputTransaction& out, const std::string& path, const AreaSet& areas,
                const WriteFormat& format);

void write_edge(OutputTransaction& out, const std::string& path, const EdgeSet& edges,
                const WriteFormat& format);

void write_neigh(OutputTransaction& out, const std::string& path, const NeighbourSet& neighbours,
                 const WriteFormat& format);

// Geomview's .off: always numbered from 0 (format.base is ignored); the
// edge count in the header is the caller's (Triangle writes its edge count).
void write_off(OutputTransaction& out, const std::string& path, const NodeSet& nodes,
               const EleSet& triangles, std::uint64_t edge_count, const WriteFormat& format);

// The Voronoi diagram: .v.node is an ordinary .node file (write_node, with
// no markers), .v.edge is this.  Rays are written "<i> <a> -1 <dx> <dy>".
void write_voronoi_edge(OutputTransaction& out, const std::string& path,
                        const VoronoiEdgeSet& edges, const WriteFormat& format);

}  // namespace gpdr::io
