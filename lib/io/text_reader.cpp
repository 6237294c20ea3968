// TextReader: loads a file in one read and walks its data lines and fields
// (see text_reader.hpp for the rules it follows and where it deviates).

#include "io/text_reader.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <system_error>

#include <fmt/format.h>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io/content_hash.hpp"

namespace gpdr::io::detail {

namespace {

bool is_blank(char c) noexcept {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

// Where a number that ends at p ends its field: p itself at a blank or the
// end of the data, p + 1 at a comma followed by either (Triangle reads
// "50, 2, 0, 0": each field is a number and what strtod leaves of it), or
// null when the field goes on ("50,2" is one field and no number).
const char* field_end(const char* p, const char* end) noexcept {
    if (p == end || is_blank(*p)) return p;
    if (*p == ',' && (p + 1 == end || is_blank(p[1]))) return p + 1;
    return nullptr;
}

// A field without the comma that may end it.
std::string_view without_comma(std::string_view field) noexcept {
    if (field.size() > 1 && field.back() == ',') field.remove_suffix(1);
    return field;
}

InputError read_failure(const std::string& path, std::string_view why_needed, std::string reason) {
    if (!why_needed.empty()) {
        reason += " (";
        reason += why_needed;
        reason += ")";
    }
    return InputError(path, 0, std::move(reason));
}

// Closes a file descriptor when it goes out of scope.
struct Descriptor {
    int fd;
    ~Descriptor() {
        if (fd >= 0) ::close(fd);
    }
};

// Parses a whole token as a finite or infinite real, the way strtod would
// for the decimal forms.  Returns false if the token is not a number.
bool parse_real(const char* b, const char* e, double& out) {
    if (b != e && *b == '+' && e - b > 1 && (b[1] == '.' || (b[1] >= '0' && b[1] <= '9'))) ++b;
    const auto [ptr, ec] = std::from_chars(b, e, out, std::chars_format::general);
    if (ptr != e) return false;
    if (ec == std::errc::result_out_of_range) {
        // Underflow or overflow: take strtod's answer (0/denormal or +-HUGE_VAL).
        const std::string copy(b, e);
        out = std::strtod(copy.c_str(), nullptr);
        return true;
    }
    return ec == std::errc{};
}

// A field for a message: at most 40 bytes, control bytes (a NUL would cut
// the message short, an escape sequence would reach the terminal) written
// as \xHH.
std::string quoted(std::string_view token) {
    std::string s = "'";
    for (const char c : token.substr(0, 40)) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte < 0x20 || byte == 0x7f || c == '\\')
            s += fmt::format("\\x{:02x}", byte);
        else
            s += c;
    }
    if (token.size() > 40) s += "...";
    s += "'";
    return s;
}

}  // namespace

FileText::FileText(const std::string& path, std::string_view why_needed, std::size_t cap) {
    const auto failure = [&](int err) {
        return read_failure(path, why_needed, std::string("cannot read: ") + std::strerror(err));
    };
    const Descriptor file{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
    if (file.fd < 0) throw failure(errno);
    struct stat st {};
    if (::fstat(file.fd, &st) != 0) throw failure(errno);
    if (S_ISDIR(st.st_mode)) throw failure(EISDIR);
    if (S_ISREG(st.st_mode)) {
        if (st.st_size == 0) return;
        const auto length = static_cast<std::size_t>(st.st_size);
        void* map = ::mmap(nullptr, length, PROT_READ, MAP_PRIVATE, file.fd, 0);
        if (map == MAP_FAILED) throw failure(errno);
        ::madvise(map, length, MADV_SEQUENTIAL);
        mapping_ = map;
        data_ = static_cast<const char*>(map);
        size_ = length;
        return;
    }
    // Not a regular file: read what comes, growing the buffer geometrically,
    // up to the cap.
    std::size_t used = 0;
    for (;;) {
        if (used == owned_.size()) {
            if (used >= cap)
                throw read_failure(path, why_needed,
                                   fmt::format("not a regular file, and longer than {} bytes: "
                                               "not read",
                                               cap));
            owned_.resize(std::min(cap, std::max<std::size_t>(65536, 2 * used)));
        }
        const ssize_t got = ::read(file.fd, owned_.data() + used, owned_.size() - used);
        if (got < 0) {
            if (errno == EINTR) continue;
            throw failure(errno);
        }
        if (got == 0) break;
        used += static_cast<std::size_t>(got);
    }
    owned_.resize(used);
    owned_.shrink_to_fit();
    data_ = owned_.data();
    size_ = owned_.size();
}

FileText::~FileText() {
    if (mapping_ != nullptr) ::munmap(mapping_, size_);
}

TextReader::TextReader(std::string path, std::string_view why_needed)
    : path_(std::move(path)), text_(path_, why_needed) {
    next_ = text_.data();
    pos_ = data_end_ = next_;
}

bool TextReader::next_line() {
    const char* const end = text_.data() + text_.size();
    if (next_ == nullptr) return false;  // already past the end
    while (next_ < end) {
        const char* start = next_;
        const auto* nl = static_cast<const char*>(std::memchr(start, '\n', end - start));
        const char* eol = nl ? nl : end;
        next_ = nl ? nl + 1 : end;
        ++line_;
        const auto* hash = static_cast<const char*>(std::memchr(start, '#', eol - start));
        data_end_ = hash ? hash : eol;
        pos_ = start;
        skip_blanks();
        if (pos_ != data_end_) return true;
    }
    // The end of the file: report the line after the last one.
    ++line_;
    next_ = nullptr;
    pos_ = data_end_ = end;
    return false;
}

std::size_t TextReader::remaining_bytes() const noexcept {
    if (next_ == nullptr) return 0;
    return static_cast<std::size_t>(text_.data() + text_.size() - next_);
}

std::uint64_t TextReader::content_hash() const noexcept {
    return hash_bytes(std::string_view(text_.data(), text_.size()));
}

void TextReader::skip_blanks() noexcept {
    while (pos_ < data_end_ && is_blank(*pos_)) ++pos_;
}

bool TextReader::has_field() {
    skip_blanks();
    return pos_ < data_end_;
}

std::string_view TextReader::token() {
    skip_blanks();
    const char* e = pos_;
    while (e < data_end_ && !is_blank(*e)) ++e;
    return {pos_, static_cast<std::size_t>(e - pos_)};
}

double TextReader::real(std::string_view what) {
    skip_blanks();
    if (pos_ == data_end_) fail(std::string(what) + " is missing");
    double value = 0;
    // Fast path: from_chars stops at the blank ending the token.
    const auto [ptr, ec] = std::from_chars(pos_, data_end_, value, std::chars_format::general);
    const char* end = ec == std::errc{} ? field_end(ptr, data_end_) : nullptr;
    if (end != nullptr) {
        if (!std::isfinite(value))
            fail(std::string(what) + " " + quoted(token()) + " is not finite");
        pos_ = end;
        return value;
    }
    const std::string_view field = token();
    const std::string_view tok = without_comma(field);
    if (!parse_real(tok.data(), tok.data() + tok.size(), value))
        fail(std::string(what) + " " + quoted(tok) + " is not a number");
    if (!std::isfinite(value)) fail(std::string(what) + " " + quoted(tok) + " is not finite");
    pos_ = field.data() + field.size();
    return value;
}

std::int64_t TextReader::integer(std::string_view what) {
    skip_blanks();
    if (pos_ == data_end_) fail(std::string(what) + " is missing");
    std::int64_t value = 0;
    const auto [ptr, ec] = std::from_chars(pos_, data_end_, value);
    const char* end = ec == std::errc{} ? field_end(ptr, data_end_) : nullptr;
    if (end != nullptr) {
        pos_ = end;
        return value;
    }
    // Slow path: "+3", "3.0", "1e2" are integers written another way.
    const std::string_view field = token();
    const std::string_view tok = without_comma(field);
    double real_value = 0;
    constexpr double limit = 4611686018427387904.0;  // 2^62: far beyond any index or count
    if (!parse_real(tok.data(), tok.data() + tok.size(), real_value) ||
        !std::isfinite(real_value) || real_value != std::floor(real_value) ||
        std::fabs(real_value) > limit)
        fail(std::string(what) + " " + quoted(tok) + " is not an integer");
    pos_ = field.data() + field.size();
    return static_cast<std::int64_t>(real_value);
}

std::int64_t TextReader::integer_or(std::int64_t fallback, std::string_view what) {
    return has_field() ? integer(what) : fallback;
}

double TextReader::real_or(double fallback, std::string_view what) {
    return has_field() ? real(what) : fallback;
}

std::size_t TextReader::count(std::string_view what, std::size_t min_bytes_per_entry) {
    const std::int64_t n = integer(what);
    if (n < 0) fail(std::string(what) + " " + std::to_string(n) + " is negative");
    // Every entry takes a line of at least min_bytes_per_entry bytes (the
    // last one may lack its newline).  A large count beyond that is not a
    // file cut short but a wrong number: refuse it here, before anything is
    // reserved.  A small one is reported where the entries run out
    // ("expected 4 vertices, found 3"), which says more to the user; the
    // readers never reserve more than the file can hold either way.
    const std::size_t capacity = (remaining_bytes() + 1) / min_bytes_per_entry;
    constexpr std::uint64_t small = 65536;
    if (static_cast<std::uint64_t>(n) > capacity && static_cast<std::uint64_t>(n) > small)
        fail(std::string(what) + " " + std::to_string(n) + " is impossible: the remaining " +
             std::to_string(remaining_bytes()) +
             " bytes of the file cannot hold that many entries");
    return static_cast<std::size_t>(n);
}

void TextReader::fail(std::string reason) const { fail_at(line_, std::move(reason)); }

void TextReader::fail_at(std::size_t line, std::string reason) const {
    throw InputError(path_, line, std::move(reason));
}

void TextReader::warn(const WarningSink& sink, std::string message) const {
    if (sink) sink(Warning{path_, line_, std::move(message)});
}

void IdChecker::check(TextReader& in, std::int64_t id, std::size_t k, const WarningSink& warn) {
    const auto expected = static_cast<std::int64_t>(k) + base_;
    if (id == expected || warned_) return;
    warned_ = true;
    in.warn(warn, std::string(kind_) + " number " + std::to_string(id) + " where " +
                      std::to_string(expected) +
                      " was expected; ids are not consecutive (gpdr, like Triangle, numbers " +
                      (kind_ == "vertex" ? std::string("vertices") : std::string(kind_) + "s") +
                      " by their order in the file; further jumps in this "
                      "file are not reported)");
}

}  // namespace gpdr::io::detail
