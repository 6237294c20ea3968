#pragma once
// How much memory a run may still use: the kernel's MemAvailable
// (/proc/meminfo), or the memory limit of the run's control group when that
// is lower (a container or a systemd slice often allows far less than the
// machine has, and the kernel kills a process that goes past it).  The
// parsers take the files' text, so that they can be tested on any machine.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gpdr::api {

// "MemAvailable:  20480000 kB" in /proc/meminfo, in bytes; none if absent.
std::optional<std::uint64_t> parse_mem_available(std::string_view meminfo);

// A cgroup memory limit file: v2's memory.max ("max" or bytes) or v1's
// memory.limit_in_bytes (bytes; "no limit" is a huge value near 2^63).
// None when there is no limit.
std::optional<std::uint64_t> parse_cgroup_limit(std::string_view text);

// The control groups of /proc/self/cgroup that can hold a memory limit:
// the v2 group ("0::/path") and the v1 group of the memory controller
// ("N:...,memory,...:/path"), as paths relative to their hierarchy's root.
struct CgroupPaths {
    std::optional<std::string> unified;
    std::optional<std::string> memory_v1;
};
CgroupPaths parse_proc_self_cgroup(std::string_view text);

// The limit files to read for those groups under `root` (normally
// /sys/fs/cgroup, where v2 is mounted itself or at unified/, and v1's
// memory controller at memory/): the group's own and every enclosing
// group's, since a limit on any of them applies.
std::vector<std::string> cgroup_limit_files(const CgroupPaths& groups, std::string_view root);

// The lowest of MemAvailable and every cgroup limit that applies; none when
// none of them can be read (not Linux, /proc not mounted).
std::optional<std::uint64_t> memory_available();

}  // namespace gpdr::api
