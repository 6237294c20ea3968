// TextReader: loads a file in one read and walks its data lines and fields
// (see text_reader.hpp for the rules it follows and where it deviates).

#include "io/text_reader.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace gpdr::io::detail {

namespace {

bool is_blank(char c) noexcept {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

std::string read_whole_file(const std::string& path, std::string_view why_needed) {
    auto failure = [&](int err) {
        std::string reason = "cannot read: ";
        reason += std::strerror(err);
        if (!why_needed.empty()) {
            reason += " (";
            reason += why_needed;
            reason += ")";
        }
        return InputError(path, 0, std::move(reason));
    };
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw failure(errno);
    struct stat st {};
    if (::fstat(fd, &st) != 0) {
        const int err = errno;
        ::close(fd);
        throw failure(err);
    }
    if (S_ISDIR(st.st_mode)) {
        ::close(fd);
        throw failure(EISDIR);
    }
    std::string text;
    // The size from fstat is a hint (a pipe or a growing file reports less);
    // read until the end either way.
    text.resize(st.st_size > 0 ? static_cast<std::size_t>(st.st_size) : 0);
    std::size_t used = 0;
    for (;;) {
        if (used == text.size()) text.resize(text.size() + 65536);
        const ssize_t got = ::read(fd, text.data() + used, text.size() - used);
        if (got < 0) {
            if (errno == EINTR) continue;
            const int err = errno;
            ::close(fd);
            throw failure(err);
        }
        if (got == 0) break;
        used += static_cast<std::size_t>(got);
    }
    ::close(fd);
    text.resize(used);
    return text;
}

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

std::string quoted(std::string_view token) {
    std::string s = "'";
    s.append(token.substr(0, 40));
    if (token.size() > 40) s += "...";
    s += "'";
    return s;
}

}  // namespace

TextReader::TextReader(std::string path, std::string_view why_needed)
    : path_(std::move(path)), text_(read_whole_file(path_, why_needed)) {
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
    if (ec == std::errc{} && (ptr == data_end_ || is_blank(*ptr))) {
        if (!std::isfinite(value))
            fail(std::string(what) + " " + quoted(token()) + " is not finite");
        pos_ = ptr;
        return value;
    }
    const std::string_view tok = token();
    if (!parse_real(tok.data(), tok.data() + tok.size(), value))
        fail(std::string(what) + " " + quoted(tok) + " is not a number");
    if (!std::isfinite(value)) fail(std::string(what) + " " + quoted(tok) + " is not finite");
    pos_ = tok.data() + tok.size();
    return value;
}

std::int64_t TextReader::integer(std::string_view what) {
    skip_blanks();
    if (pos_ == data_end_) fail(std::string(what) + " is missing");
    std::int64_t value = 0;
    const auto [ptr, ec] = std::from_chars(pos_, data_end_, value);
    if (ec == std::errc{} && (ptr == data_end_ || is_blank(*ptr))) {
        pos_ = ptr;
        return value;
    }
    // Slow path: "+3", "3.0", "1e2" are integers written another way.
    const std::string_view tok = token();
    double real_value = 0;
    constexpr double limit = 4611686018427387904.0;  // 2^62: far beyond any index or count
    if (!parse_real(tok.data(), tok.data() + tok.size(), real_value) ||
        !std::isfinite(real_value) || real_value != std::floor(real_value) ||
        std::fabs(real_value) > limit)
        fail(std::string(what) + " " + quoted(tok) + " is not an integer");
    pos_ = tok.data() + tok.size();
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
