#pragma once
// A reader for the .vtu files gpdr writes (VTK XML UnstructuredGrid, raw
// appended data, UInt64 block sizes), written from VTK's description of the
// format and independent of the writer: it finds each DataArray in the XML
// head by name, and its bytes at its offset after the '_' that starts the
// appended data.

#include <cstdint>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace gpdr::test {

class VtuFile {
public:
    struct Array {
        std::string type;
        unsigned components = 1;
        std::string section;  // PointData, CellData, Points or Cells
        std::string bytes;    // the values, as stored
    };

    explicit VtuFile(std::string text) : text_(std::move(text)) {
        const std::size_t appended = text_.find("<AppendedData encoding=\"raw\">");
        if (appended == std::string::npos) throw std::runtime_error("no raw AppendedData");
        const std::size_t underscore = text_.find('_', appended);
        head_ = text_.substr(0, appended);
        points_ = attribute_of(head_, "<Piece", "NumberOfPoints");
        cells_ = attribute_of(head_, "<Piece", "NumberOfCells");
        std::string section;
        for (std::size_t at = 0; (at = head_.find('<', at)) != std::string::npos; ++at) {
            const std::size_t end = head_.find('>', at);
            const std::string tag = head_.substr(at, end - at + 1);
            for (const char* s : {"PointData", "CellData", "Points", "Cells"})
                if (tag == std::string("<") + s + ">") section = s;
            if (tag.rfind("<DataArray", 0) != 0) continue;
            Array a;
            a.type = value(tag, "type");
            a.section = section;
            const std::string components = value(tag, "NumberOfComponents", "1");
            a.components = static_cast<unsigned>(std::stoul(components));
            if (value(tag, "format") != "appended") throw std::runtime_error("not appended");
            const std::size_t offset = std::stoull(value(tag, "offset"));
            const std::size_t start = underscore + 1 + offset;
            std::uint64_t size = 0;
            if (start + 8 > text_.size()) throw std::runtime_error("offset past the end");
            std::memcpy(&size, text_.data() + start, 8);
            if (start + 8 + size > text_.size()) throw std::runtime_error("array past the end");
            a.bytes = text_.substr(start + 8, size);
            arrays_[value(tag, "Name")] = std::move(a);
        }
    }

    const std::string& head() const { return head_; }
    const std::string& text() const { return text_; }
    std::size_t points() const { return points_; }
    std::size_t cells() const { return cells_; }
    bool has(const std::string& name) const { return arrays_.count(name) > 0; }
    const Array& array(const std::string& name) const { return arrays_.at(name); }

    // The values of array `name`, which must have type `type`.
    template <class T>
    std::vector<T> values(const std::string& name, const std::string& type) const {
        const Array& a = array(name);
        if (a.type != type) throw std::runtime_error(name + " is " + a.type + ", not " + type);
        if (a.bytes.size() % sizeof(T) != 0) throw std::runtime_error(name + ": ragged size");
        std::vector<T> v(a.bytes.size() / sizeof(T));
        std::memcpy(v.data(), a.bytes.data(), a.bytes.size());
        return v;
    }
    // Integers of either width, as 64-bit.
    std::vector<std::int64_t> integers(const std::string& name) const {
        if (array(name).type == "Int32") {
            const auto narrow = values<std::int32_t>(name, "Int32");
            return {narrow.begin(), narrow.end()};
        }
        return values<std::int64_t>(name, "Int64");
    }

private:
    static std::string value(const std::string& tag, const std::string& key,
                             const std::string& otherwise = "") {
        const std::size_t at = tag.find(" " + key + "=\"");
        if (at == std::string::npos) {
            if (!otherwise.empty()) return otherwise;
            throw std::runtime_error("no " + key + " in " + tag);
        }
        const std::size_t begin = at + key.size() + 3;
        return tag.substr(begin, tag.find('"', begin) - begin);
    }
    static std::size_t attribute_of(const std::string& head, const std::string& element,
                                    const std::string& key) {
        const std::size_t at = head.find(element);
        if (at == std::string::npos) throw std::runtime_error("no " + element);
        return std::stoull(value(head.substr(at, head.find('>', at) - at + 1), key));
    }

    std::string text_, head_;
    std::size_t points_ = 0, cells_ = 0;
    std::map<std::string, Array> arrays_;
};

}  // namespace gpdr::test
