// TextReader: walks the data lines and fields of a file as LineSource hands
// its lines over (see text_reader.hpp for the rules it follows and where it
// deviates).

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

// A field for a message: at most 40 bytes, control bytes (an escape
// sequence would reach the terminal) and bytes outside ASCII (C1 controls
// such as 0x9b, the one-byte CSI, and the noise of a binary file, which
// would not be text in the message) written as \xHH.
std::string quoted(std::string_view token) {
    std::string s = "'";
    for (const char c : token.substr(0, 40)) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte < 0x20 || byte >= 0x7f || c == '\\')
            s += fmt::format("\\x{:02x}", byte);
        else
            s += c;
    }
    if (token.size() > 40) s += "...";
    s += "'";
    return s;
}

}  // namespace

TextReader::TextReader(std::string path, std::string_view why_needed)
    : path_(std::move(path)), source_(path_, why_needed) {}

TextReader::TextReader(std::string path, std::string_view bytes, LineSource::Borrowed tag)
    : path_(std::move(path)), source_(path_, bytes, tag) {}

bool TextReader::next_line() {
    if (at_end_) return false;
    while (source_.next_line()) {
        const std::string_view text = source_.text();
        const char* const eol = text.data() + text.size();
        const auto* hash = static_cast<const char*>(std::memchr(text.data(), '#', text.size()));
        line_ = source_.line();
        data_end_ = hash != nullptr ? hash : eol;
        pos_ = text.data();
        skip_blanks();
        if (pos_ != data_end_) return true;
    }
    // The end of the file: report the line after the last one.
    at_end_ = true;
    line_ = source_.line() + 1;
    pos_ = data_end_ = nullptr;
    return false;
}

std::uint64_t TextReader::finish() {
    const std::uint64_t hash = source_.finish();
    for (const RestClaim& claim : claims_) {
        const std::uint64_t rest = source_.bytes_read() - claim.from;
        if (rest < claim.bytes) fail_at(claim.line, claim.reason(rest));
    }
    return hash;
}

void TextReader::require_rest(std::uint64_t bytes,
                              std::function<std::string(std::uint64_t)> reason) {
    if (sized()) {
        if (remaining_bytes() < bytes) fail(reason(remaining_bytes()));
        return;
    }
    claims_.push_back(RestClaim{line_, source_.offset(), bytes, std::move(reason)});
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
    if (has_field()) return real(what);
    if (!sized()) count_left_out(what);
    return fallback;
}

void TextReader::count_left_out(std::string_view what) {
    const std::uint64_t read = source_.bytes_read();
    if (++left_out_ > left_out_slack + read / 2)
        fail(
            fmt::format("{} values left out of their lines so far, the last a {}: more than "
                        "input that is not a regular file may leave out ({} plus one for every "
                        "two of the {} bytes read)",
                        left_out_, what, left_out_slack, read));
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
    // A stream's size is not known yet: see reserve_hint().
    const std::size_t capacity = (remaining_bytes() + 1) / min_bytes_per_entry;
    constexpr std::uint64_t small = 65536;
    if (sized() && static_cast<std::uint64_t>(n) > capacity &&
        static_cast<std::uint64_t>(n) > small)
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
    in.warn(warn, jump_message(kind_, id, expected));
}

std::string IdChecker::jump_message(std::string_view kind, std::int64_t id, std::int64_t expected) {
    return std::string(kind) + " number " + std::to_string(id) + " where " +
           std::to_string(expected) +
           " was expected; ids are not consecutive (gpdr, like Triangle, numbers " +
           (kind == "vertex" ? std::string("vertices") : std::string(kind) + "s") +
           " by their order in the file; further jumps in this "
           "file are not reported)";
}

}  // namespace gpdr::io::detail
