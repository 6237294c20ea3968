// LineSource: the lines of a mapped regular file or of a stream read as it
// arrives, each checked for NUL bytes and length (see line_source.hpp).

#include "io/line_source.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <utility>

#include <gpdr/errors.hpp>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

namespace gpdr::io::detail {

namespace {

// How far ahead of the line being checked one search for NUL bytes goes: one
// memchr call for many short lines, not one per line.
constexpr std::size_t nul_search_bytes = std::size_t{1} << 20;

InputError open_failure(const std::string& path, std::string_view why_needed, int err) {
    std::string reason = std::string("cannot read: ") + std::strerror(err);
    if (!why_needed.empty()) {
        reason += " (";
        reason += why_needed;
        reason += ")";
    }
    return InputError(path, 0, std::move(reason));
}

// Closes a file descriptor when it goes out of scope, unless released.
struct Descriptor {
    int fd;
    ~Descriptor() {
        if (fd >= 0) ::close(fd);
    }
    int release() noexcept { return std::exchange(fd, -1); }
};

}  // namespace

LineSource::LineSource(const std::string& path, std::string_view why_needed) : path_(path) {
    Descriptor file{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
    if (file.fd < 0) throw open_failure(path, why_needed, errno);
    struct stat st {};
    if (::fstat(file.fd, &st) != 0) throw open_failure(path, why_needed, errno);
    if (S_ISDIR(st.st_mode)) throw open_failure(path, why_needed, EISDIR);
    if (S_ISREG(st.st_mode)) {
        if (st.st_size == 0) return;
        const auto length = static_cast<std::size_t>(st.st_size);
        void* map = ::mmap(nullptr, length, PROT_READ, MAP_PRIVATE, file.fd, 0);
        if (map == MAP_FAILED) throw open_failure(path, why_needed, errno);
        ::madvise(map, length, MADV_SEQUENTIAL);
        mapping_ = map;
        mapping_size_ = length;
        base_ = next_ = line_begin_ = line_end_ = static_cast<const char*>(map);
        newline_scanned_ = nul_scanned_ = base_;
        end_ = base_ + length;
        return;
    }
    // A pipe, a fifo, a device: read as it comes.
    stream_ = true;
    eof_ = false;
    capacity_ = read_bytes;
    buffer_.reset(new char[capacity_]);
    base_ = end_ = next_ = line_begin_ = line_end_ = buffer_.get();
    newline_scanned_ = nul_scanned_ = base_;
    fd_ = file.release();
}

LineSource::LineSource(const std::string& path, std::string_view bytes, Borrowed) : path_(path) {
    if (bytes.empty()) return;
    base_ = next_ = line_begin_ = line_end_ = newline_scanned_ = nul_scanned_ = bytes.data();
    end_ = base_ + bytes.size();
}

void LineSource::resume_at(std::uint64_t offset, std::size_t line) noexcept {
    next_ = line_begin_ = line_end_ = newline_scanned_ = nul_scanned_ = base_ + offset;
    nul_ = nullptr;
    line_ = line;
}

LineSource::~LineSource() {
    if (mapping_ != nullptr) ::munmap(mapping_, mapping_size_);
    if (fd_ >= 0) ::close(fd_);
}

bool LineSource::next_line_slowly() {
    for (;;) {
        const char* newline = nullptr;
        if (newline_scanned_ < end_) {
            newline = static_cast<const char*>(
                std::memchr(newline_scanned_, '\n', std::size_t(end_ - newline_scanned_)));
            newline_scanned_ = newline != nullptr ? newline : end_;
        }
        if (newline != nullptr || eof_) {
            if (newline == nullptr && next_ == end_) return false;
            const char* eol = newline != nullptr ? newline : end_;
            check(next_, eol, line_ + 1);
            ++line_;
            line_begin_ = next_;
            line_end_ = eol;
            next_ = newline != nullptr ? newline + 1 : end_;
            newline_scanned_ = next_;
            return true;
        }
        // A stream, and no whole line in memory: what there is of it must
        // pass before more is read, so that /dev/zero stops here.
        check(next_, end_, line_ + 1);
        refill();
    }
}

void LineSource::check(const char* b, const char* e, std::size_t line) {
    const auto length = std::size_t(e - b);
    if (first_nul_before(b + std::min(length, max_line_bytes)) != nullptr)
        fail_at(line, "a NUL byte: not a text file");
    if (length > max_line_bytes) fail_at(line, "line longer than 1 MiB");
}

const char* LineSource::first_nul_before(const char* to) noexcept {
    if (nul_ != nullptr) return nul_ < to ? nul_ : nullptr;
    const char* from = std::max(nul_scanned_, next_);
    if (from >= to) return nullptr;
    const auto ahead = std::min(std::size_t(end_ - from), nul_search_bytes);
    const char* stop = std::max(to, from + ahead);
    nul_ = static_cast<const char*>(std::memchr(from, '\0', std::size_t(stop - from)));
    nul_scanned_ = stop;
    return nul_ != nullptr && nul_ < to ? nul_ : nullptr;
}

void LineSource::refill() {
    // Keep only the partial line (checked: at most max_line_bytes), at the
    // start of a buffer with room for one more read behind it.
    const auto kept = std::size_t(end_ - next_);
    char* target = buffer_.get();
    std::unique_ptr<char[]> bigger;
    if (kept + read_bytes > capacity_) {
        std::size_t capacity = capacity_;
        while (capacity < kept + read_bytes) capacity *= 2;
        bigger.reset(new char[capacity]);
        target = bigger.get();
        capacity_ = capacity;
    }
    if (target != next_) std::memmove(target, next_, kept);
    const auto moved = [&](const char* p) { return target + (p - next_); };
    newline_scanned_ = moved(newline_scanned_);
    nul_scanned_ = moved(std::max(nul_scanned_, next_));
    if (nul_ != nullptr) nul_ = moved(nul_);
    dropped_ += std::uint64_t(next_ - base_);
    if (bigger) buffer_ = std::move(bigger);
    base_ = next_ = line_begin_ = line_end_ = target;
    end_ = target + kept;

    for (;;) {
        const ssize_t got = ::read(fd_, target + kept, capacity_ - kept);
        if (got < 0) {
            if (errno == EINTR) continue;
            fail_at(0, std::string("cannot read: ") + std::strerror(errno));
        }
        if (got == 0) {
            eof_ = true;
            return;
        }
        hasher_.add(std::string_view(end_, std::size_t(got)));
        end_ += got;
        return;
    }
}

std::uint64_t LineSource::finish() {
    while (next_line()) {}
    if (stream_) return hasher_.value();
    if (hash_adopted_) return adopted_hash_;
    return hash_bytes(std::string_view(base_, std::size_t(end_ - base_)));
}

void LineSource::fail_at(std::size_t line, std::string reason) const {
    throw InputError(path_, line, std::move(reason));
}

}  // namespace gpdr::io::detail
