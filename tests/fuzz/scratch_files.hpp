#pragma once
// The readers take file names, so a reader's fuzz target writes each input
// into files first: in a folder of its own, made once per process in
// /dev/shm when there is one (no disk traffic on every run), removed when the
// process ends normally.
//
// One fuzz input may hold several files, one after the other, separated by
// a line "@@" (the separator's newline ends the file before it).  Seeds
// written by hand stay readable that way, and the fuzzer finds the
// separator by its comparison tracing.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace gpdr::fuzz {

// The fuzz input as text, cut into its files: at most `max_parts` parts (the
// last one keeps any further separators).
std::vector<std::string_view> split_parts(const std::uint8_t* data, std::size_t size,
                                          std::size_t max_parts);

// Writes `text` to <folder>/<name> and returns that path.  Aborts when the
// file cannot be written: a harness problem, not a finding.
std::string write_scratch_file(std::string_view name, std::string_view text);

// Removes <folder>/<name> if it is there (a part this input does not have
// must not be read as the previous input's).
void remove_scratch_file(std::string_view name);

// The path <folder>/<name>, whether or not the file exists.
std::string scratch_path(std::string_view name);

}  // namespace gpdr::fuzz
