// How much memory a run may still use (see memory_available.hpp).

#include "api/memory_available.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>

namespace gpdr::api {
namespace {

std::string_view trim(std::string_view s) {
    const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
    while (!s.empty() && blank(s.front())) s.remove_prefix(1);
    while (!s.empty() && blank(s.back())) s.remove_suffix(1);
    return s;
}

std::optional<std::uint64_t> whole_number(std::string_view s) {
    std::uint64_t n = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), n);
    if (ec != std::errc() || end == s.data() || end != s.data() + s.size()) return std::nullopt;
    return n;
}

// Calls f(line) for each line of `text`, without its '\n'.
template <class F>
void for_each_line(std::string_view text, F&& f) {
    while (!text.empty()) {
        const std::size_t end = std::min(text.find('\n'), text.size());
        f(text.substr(0, end));
        text.remove_prefix(std::min(end + 1, text.size()));
    }
}

// A small file of /proc or /sys, whole; none if it cannot be read.  These
// files report a size of 0, so they are read until the end.
std::optional<std::string> read_small_file(const std::string& path) {
    std::FILE* f = std::fopen(path.c_str(), "re");
    if (f == nullptr) return std::nullopt;
    std::string text;
    char chunk[4096];
    std::size_t n = 0;
    while ((n = std::fread(chunk, 1, sizeof chunk, f)) > 0 && text.size() < (1u << 20))
        text.append(chunk, n);
    const bool failed = std::ferror(f) != 0;
    std::fclose(f);
    if (failed) return std::nullopt;
    return text;
}

}  // namespace

std::optional<std::uint64_t> parse_mem_available(std::string_view meminfo) {
    std::optional<std::uint64_t> found;
    for_each_line(meminfo, [&](std::string_view line) {
        constexpr std::string_view key = "MemAvailable:";
        if (found || line.substr(0, key.size()) != key) return;
        std::string_view value = trim(line.substr(key.size()));
        std::uint64_t unit = 1;
        if (value.size() > 2 && value.substr(value.size() - 2) == "kB") {
            unit = 1024;
            value = trim(value.substr(0, value.size() - 2));
        }
        const auto n = whole_number(value);
        if (n) found = *n * unit;
    });
    return found;
}

std::optional<std::uint64_t> parse_cgroup_limit(std::string_view text) {
    const std::string_view value = trim(text);
    if (value == "max") return std::nullopt;
    const auto n = whole_number(value);
    // cgroup v1 writes "no limit" as the largest page-aligned signed value,
    // 0x7ffffffffffff000 on 4 KiB pages: treat anything that large as none.
    if (!n || *n >= (std::uint64_t{1} << 62)) return std::nullopt;
    return n;
}

CgroupPaths parse_proc_self_cgroup(std::string_view text) {
    CgroupPaths groups;
    for_each_line(text, [&](std::string_view line) {
        // "hierarchy-ID:controller-list:path"; the path may itself hold ':'.
        const std::size_t first = line.find(':');
        if (first == std::string_view::npos) return;
        const std::size_t second = line.find(':', first + 1);
        if (second == std::string_view::npos) return;
        const std::string_view id = line.substr(0, first);
        const std::string_view controllers = line.substr(first + 1, second - first - 1);
        const std::string path(line.substr(second + 1));
        if (path.empty() || path.front() != '/') return;
        if (id == "0" && controllers.empty()) {
            groups.unified = path;
            return;
        }
        std::string_view rest = controllers;
        while (!rest.empty()) {
            const std::size_t comma = std::min(rest.find(','), rest.size());
            if (rest.substr(0, comma) == "memory") groups.memory_v1 = path;
            rest.remove_prefix(std::min(comma + 1, rest.size()));
        }
    });
    return groups;
}

std::vector<std::string> cgroup_limit_files(const CgroupPaths& groups, std::string_view root) {
    std::vector<std::string> files;
    // The group's folder under the hierarchy's mount point, then each
    // enclosing one up to the mount point itself (which, in a container,
    // is often the container's own group while /proc/self/cgroup names
    // its path on the host).  A file that is absent just finds nothing.
    const auto up_to_root = [&](const std::string& mount, std::string group,
                                std::string_view file) {
        while (group.size() > 1 && group.back() == '/') group.pop_back();
        while (true) {
            files.push_back(mount + (group == "/" ? "" : group) + "/" + std::string(file));
            if (group == "/") break;
            const std::size_t slash = group.rfind('/');
            group = slash == 0 ? "/" : group.substr(0, slash);
        }
    };
    const std::string base(root);
    // v2 is mounted at the root, or at unified/ beside the v1 hierarchies.
    if (groups.unified) {
        up_to_root(base, *groups.unified, "memory.max");
        up_to_root(base + "/unified", *groups.unified, "memory.max");
    }
    if (groups.memory_v1) up_to_root(base + "/memory", *groups.memory_v1, "memory.limit_in_bytes");
    return files;
}

std::optional<std::uint64_t> memory_available() {
    std::optional<std::uint64_t> least;
    const auto consider = [&least](std::optional<std::uint64_t> n) {
        if (n) least = least ? std::min(*least, *n) : *n;
    };
    if (const auto meminfo = read_small_file("/proc/meminfo"))
        consider(parse_mem_available(*meminfo));
    if (const auto cgroup = read_small_file("/proc/self/cgroup")) {
        for (const std::string& file :
             cgroup_limit_files(parse_proc_self_cgroup(*cgroup), "/sys/fs/cgroup"))
            if (const auto text = read_small_file(file)) consider(parse_cgroup_limit(*text));
    }
    return least;
}

}  // namespace gpdr::api
