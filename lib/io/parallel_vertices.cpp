// The vertex lines of a mapped file, parsed in slices on several threads and
// joined in file order (see parallel_vertices.hpp).

#include "io/parallel_vertices.hpp"

#include <algorithm>
#include <cstring>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <gpdr/errors.hpp>

#include "io/content_hash.hpp"
#include "io/read_settings.hpp"
#include "io/task_threads.hpp"

namespace gpdr::io::detail {

namespace {

// Slices per thread: enough that a thread busy with the hash, or one slow
// slice, leaves the others work to take.
constexpr std::size_t slices_per_thread = 8;
// More threads than this gain nothing on the bandwidth of one file (and
// -j1000 must not start a thousand).
constexpr unsigned max_threads = 64;

unsigned reading_threads(const ReadSettings& settings) {
    return std::min(settings.threads, max_threads);
}

// One slice of the vertex lines and what parsing it found.  Line numbers
// are counted from the slice's first line (1); offsets from its first byte.
struct Slice {
    std::string_view bytes;           // whole lines
    bool parsed = false;              // false: skipped, the slices before it end the list
    NodeSet nodes;                    // the slice's vertices (a failed line's may be partial)
    std::size_t vertices = 0;         // data lines parsed whole, before any error
    std::size_t lines = 0;            // all of its lines (only when there is no error)
    std::optional<InputError> error;  // its first error
    std::uint64_t after_last = 0;     // the end of its last vertex line...
    std::size_t after_last_line = 0;  // ... and that line
    // The vertex numbers: the first, and the first line whose number is
    // not the first + its index (so the join can check them against the
    // numbers the slices before it end with).  `numbered` counts the lines
    // whose number was read: the vertices, and a failed line past its number.
    std::size_t numbered = 0;
    std::int64_t first_id = 0;
    std::size_t first_id_line = 0;
    std::size_t jump = 0;  // index of the first jump; numbered if none
    std::int64_t jump_id = 0;
    std::size_t jump_line = 0;
};

// Cuts `bytes` into `count` slices that begin at line starts (some may be
// empty: a line longer than a slice, or fewer lines than slices).
std::vector<Slice> cut_slices(std::string_view bytes, std::size_t count) {
    std::vector<Slice> slices(count);
    std::size_t begin = 0;
    for (std::size_t i = 0; i < count; ++i) {
        std::size_t end = bytes.size();
        if (i + 1 < count) {
            const std::size_t target = std::max(begin, bytes.size() * (i + 1) / count);
            // The line holding byte target - 1 ends the slice.
            if (target > begin && bytes[target - 1] != '\n') {
                const auto* nl = static_cast<const char*>(
                    std::memchr(bytes.data() + target, '\n', bytes.size() - target));
                end = nl != nullptr ? std::size_t(nl - bytes.data()) + 1 : bytes.size();
            } else {
                end = target;
            }
        }
        slices[i].bytes = bytes.substr(begin, end - begin);
        begin = end;
    }
    return slices;
}

void note_id(Slice& s, std::int64_t id, std::size_t line) {
    if (s.numbered == 0) {
        s.first_id = id;
        s.first_id_line = line;
        s.jump = 1;
    } else if (s.jump == s.numbered) {
        if (id == s.first_id + static_cast<std::int64_t>(s.numbered)) {
            s.jump = s.numbered + 1;
        } else {
            s.jump_id = id;
            s.jump_line = line;
        }
    }
    ++s.numbered;
}

// Parses every data line of the slice as a vertex, up to its first error.
void parse_slice(const std::string& path, const NodeHeader& h, std::size_t expected, Slice& s) {
    TextReader in(path, s.bytes, LineSource::Borrowed{});
    s.nodes.attribute_count = h.attributes;
    s.nodes.xy.reserve(2 * expected);
    s.nodes.attributes.reserve(expected * h.attributes);
    if (h.markers) s.nodes.markers.reserve(expected);
    try {
        while (in.next_line()) {
            note_id(s, in.integer("vertex number"), in.line());
            read_vertex_fields(in, h, s.nodes);
            ++s.vertices;
            s.after_last = in.offset();
            s.after_last_line = in.line();
        }
        s.lines = in.line() - 1;
    } catch (const InputError& e) {
        s.error = e;
    }
    s.parsed = true;
}

// Which slices are still needed: a slice with an error, or one that
// completes `count` vertices with the slices before it, ends the list, and
// the slices after it are skipped if not yet started.  A slice's results
// are read here only once its thread has reported it parsed (under the
// lock, which orders its writes before these reads).
class Progress {
public:
    Progress(const std::vector<Slice>& slices, std::size_t count)
        : slices_(slices), count_(count), needed_(slices.size()), parsed_(slices.size(), false) {}

    bool needed(std::size_t i) {
        const std::lock_guard<std::mutex> lock(mutex_);
        return i < needed_;
    }
    void parsed(std::size_t i) {
        const std::lock_guard<std::mutex> lock(mutex_);
        parsed_[i] = true;
        if (slices_[i].error) needed_ = std::min(needed_, i + 1);
        while (done_ < needed_ && parsed_[done_] && !slices_[done_].error) {
            vertices_ += slices_[done_].vertices;
            ++done_;
            if (vertices_ >= count_) needed_ = std::min(needed_, done_);
        }
    }

private:
    std::mutex mutex_;
    const std::vector<Slice>& slices_;
    std::size_t count_;
    std::size_t needed_;
    std::vector<bool> parsed_;
    std::size_t done_ = 0;      // slices 0 .. done_ - 1 parsed without error...
    std::size_t vertices_ = 0;  // ... holding this many vertices
};

// Where the joined slices put the vertices and where the list ends.
struct Join {
    std::vector<std::size_t> first_vertex;  // per slice taken: its first vertex's index
    std::vector<std::size_t> taken;         // per slice taken: how many of its vertices
    std::uint64_t end_offset = 0;           // after the last vertex line, in the file
    std::size_t end_line = 0;               // that line
    std::size_t found = 0;                  // the vertices found (fewer: the file ended first)
    std::size_t lines = 0;                  // the file's lines, when it ended first
};

// The vertex numbering warnings of the vertices in `s` (the first at index
// `first`), as IdChecker gives them on one thread.
class IdJoin {
public:
    IdJoin(const std::string& path, int default_base, const WarningSink& warn)
        : path_(path), default_base_(default_base), base_(default_base), warn_(warn) {}

    int base() const noexcept { return base_; }

    void check(const Slice& s, std::size_t first, std::size_t count, std::size_t line_before) {
        if (s.numbered == 0 || first >= count) return;
        if (first == 0) {
            // The first vertex sets the base, as in read_vertices.
            if (s.first_id == 0 || s.first_id == 1) {
                base_ = static_cast<int>(s.first_id);
            } else {
                say(line_before + s.first_id_line, odd_first_id_message(s.first_id, default_base_));
                warned_ = true;  // the numbers are off from the start: no more reports
            }
        } else if (!warned_ && s.first_id != static_cast<std::int64_t>(first) + base_) {
            say(line_before + s.first_id_line,
                IdChecker::jump_message("vertex", s.first_id,
                                        static_cast<std::int64_t>(first) + base_));
            warned_ = true;
        }
        if (!warned_ && s.jump < s.numbered && first + s.jump < count) {
            say(line_before + s.jump_line,
                IdChecker::jump_message("vertex", s.jump_id,
                                        static_cast<std::int64_t>(first + s.jump) + base_));
            warned_ = true;
        }
    }

private:
    void say(std::size_t line, std::string message) const {
        if (warn_) warn_(Warning{path_, line, std::move(message)});
    }

    const std::string& path_;
    int default_base_;
    int base_;
    const WarningSink& warn_;
    bool warned_ = false;
};

// The end of the n-th data line (n >= 1) of a slice, as an offset and line.
std::pair<std::uint64_t, std::size_t> end_of_data_line(const std::string& path, const Slice& s,
                                                       std::size_t n) {
    if (n == s.vertices) return {s.after_last, s.after_last_line};
    TextReader in(path, s.bytes, LineSource::Borrowed{});
    for (std::size_t k = 0; k < n; ++k) in.next_line();
    return {in.offset(), in.line()};
}

// Copies the first `taken` vertices of `from` to index `first` of `to`.
void place(const Slice& from, std::size_t first, std::size_t taken, NodeSet& to) {
    const NodeSet& f = from.nodes;
    std::copy_n(f.xy.begin(), 2 * taken, to.xy.begin() + std::ptrdiff_t(2 * first));
    const std::size_t a = to.attribute_count;
    std::copy_n(f.attributes.begin(), a * taken, to.attributes.begin() + std::ptrdiff_t(a * first));
    if (!to.markers.empty())
        std::copy_n(f.markers.begin(), taken, to.markers.begin() + std::ptrdiff_t(first));
}

// Room to reserve in a slice of `bytes` bytes of the `total` after the
// header: its share of the `count` vertices, and a little more (lines vary
// in length), but never more than its bytes could hold.
std::size_t expected_vertices(std::size_t count, std::size_t bytes, std::size_t total) {
    if (total == 0) return 0;
    const double share = double(count) * double(bytes) / double(total);
    const auto generous = static_cast<std::size_t>(share * 1.05) + 16;
    return std::min({count, generous, bytes / 5 + 1});
}

void size_for(NodeSet& nodes, const NodeHeader& h) {
    nodes.xy.resize(2 * h.count);
    nodes.attributes.resize(h.count * h.attributes);
    if (h.markers) nodes.markers.resize(h.count);
}

// Joins the parsed slices in file order, from offset `start` (line
// `header_line`) on: which of each slice's vertices are taken and where
// the list ends.  The first error before the list ends is the file's
// (thrown), and the numbering warnings come before it.
Join join_slices(const std::string& path, const std::vector<Slice>& slices, const NodeHeader& h,
                 std::uint64_t start, std::size_t header_line, IdJoin& ids) {
    Join join;
    std::size_t lines_before = header_line;
    std::uint64_t offset = start;
    for (const Slice& s : slices) {
        // Progress skips only slices past one that ends the list or fails.
        if (!s.parsed) throw InternalError("parallel reading skipped a slice it needed");
        ids.check(s, join.found, h.count, lines_before);
        if (join.found + s.vertices >= h.count) {
            const std::size_t n = h.count - join.found;
            join.first_vertex.push_back(join.found);
            join.taken.push_back(n);
            if (n == 0) {
                join.end_offset = offset;
                join.end_line = lines_before;
            } else {
                const auto [end, line] = end_of_data_line(path, s, n);
                join.end_offset = offset + end;
                join.end_line = lines_before + line;
            }
            join.found = h.count;
            return join;
        }
        if (s.error)
            throw InputError(s.error->file(), lines_before + s.error->line(), s.error->reason());
        join.first_vertex.push_back(join.found);
        join.taken.push_back(s.vertices);
        join.found += s.vertices;
        lines_before += s.lines;
        offset += s.bytes.size();
    }
    join.lines = lines_before;
    return join;
}

}  // namespace

std::size_t vertex_slices(const TextReader& in, const ReadSettings& settings) {
    if (settings.threads < 2 || !in.sized()) return 1;
    const std::size_t most = slices_per_thread * reading_threads(settings);
    if (settings.min_slice_bytes == 0) return most;
    return std::clamp<std::size_t>(in.remaining_bytes() / settings.min_slice_bytes, 1, most);
}

NodeSet read_vertices_in_parallel(TextReader& in, const NodeHeader& h, int default_base, int& base,
                                  const WarningSink& warn, const ReadSettings& settings) {
    const std::string_view file = in.bytes();
    const std::uint64_t start = in.offset();
    const std::size_t header_line = in.line();
    const std::string_view rest = file.substr(start);
    std::vector<Slice> slices = cut_slices(rest, vertex_slices(in, settings));
    Progress progress(slices, h.count);

    // Tasks: the hash, the result's arrays (only if the file can hold the
    // vertices its header announces: a vertex line takes 6 bytes or more,
    // the last one 5), then the slices in file order.
    constexpr std::size_t hash_task = 0, allocate_task = 1, first_slice_task = 2;
    std::uint64_t hash = 0;
    NodeSet nodes;
    nodes.attribute_count = h.attributes;
    const bool can_hold = h.count <= (rest.size() + 1) / 6;
    run_tasks(reading_threads(settings), first_slice_task + slices.size(), [&](std::size_t task) {
        if (task == hash_task) {
            hash = hash_bytes(file);
        } else if (task == allocate_task) {
            if (can_hold) size_for(nodes, h);
        } else {
            const std::size_t i = task - first_slice_task;
            if (!progress.needed(i)) return;
            parse_slice(in.path(), h,
                        expected_vertices(h.count, slices[i].bytes.size(), rest.size()), slices[i]);
            progress.parsed(i);
        }
    });

    IdJoin ids(in.path(), default_base, warn);
    const Join join = join_slices(in.path(), slices, h, start, header_line, ids);
    base = ids.base();
    if (join.found < h.count) {
        // The file ended first: report it on the line after its last.
        in.resume_at(file.size(), join.lines, hash);
        in.next_line();
        in.fail(fmt::format("expected {} vertices, found {}", h.count, join.found));
    }

    if (nodes.xy.size() != 2 * h.count) size_for(nodes, h);
    run_tasks(reading_threads(settings), join.taken.size(), [&](std::size_t i) {
        place(slices[i], join.first_vertex[i], join.taken[i], nodes);
        slices[i].nodes = NodeSet{};
    });
    in.resume_at(join.end_offset, join.end_line, hash);
    return nodes;
}

}  // namespace gpdr::io::detail
