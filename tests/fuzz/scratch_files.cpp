// The scratch folder of a reader's fuzz target (scratch_files.hpp).

#include "fuzz/scratch_files.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace gpdr::fuzz {
namespace {

constexpr std::string_view separator = "\n@@\n";

class ScratchFolder {
public:
    ScratchFolder() {
        namespace fs = std::filesystem;
        std::error_code ec;
        fs::path root =
            fs::is_directory("/dev/shm", ec) ? fs::path("/dev/shm") : fs::temp_directory_path();
        std::string pattern = (root / "gpdr-fuzz-XXXXXX").string();
        if (!mkdtemp(pattern.data())) {
            std::perror("gpdr fuzz: cannot make a scratch folder");
            std::abort();
        }
        path_ = pattern;
    }
    ~ScratchFolder() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    ScratchFolder(const ScratchFolder&) = delete;
    ScratchFolder& operator=(const ScratchFolder&) = delete;

    const std::string& path() const noexcept { return path_; }

private:
    std::string path_;
};

const ScratchFolder& folder() {
    static const ScratchFolder f;
    return f;
}

}  // namespace

std::vector<std::string_view> split_parts(const std::uint8_t* data, std::size_t size,
                                          std::size_t max_parts) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    std::vector<std::string_view> parts;
    while (parts.size() + 1 < max_parts) {
        // A separator at the very start has no newline before it.
        if (text.starts_with(separator.substr(1))) {
            parts.emplace_back();
            text.remove_prefix(separator.size() - 1);
            continue;
        }
        const std::size_t at = text.find(separator);
        if (at == std::string_view::npos) break;
        parts.push_back(text.substr(0, at + 1));
        text.remove_prefix(at + separator.size());
    }
    parts.push_back(text);
    return parts;
}

std::string scratch_path(std::string_view name) {
    return folder().path() + "/" + std::string(name);
}

std::string write_scratch_file(std::string_view name, std::string_view text) {
    const std::string path = scratch_path(name);
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f || std::fwrite(text.data(), 1, text.size(), f) != text.size() || std::fclose(f) != 0) {
        std::perror(("gpdr fuzz: cannot write " + path).c_str());
        std::abort();
    }
    return path;
}

void remove_scratch_file(std::string_view name) {
    std::error_code ec;
    std::filesystem::remove(scratch_path(name), ec);
}

}  // namespace gpdr::fuzz
