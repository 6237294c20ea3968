#include "mesh/vertex_attributes.hpp"

#include <cstdlib>
#include <new>

#include "mesh/mesh.hpp"

namespace gpdr::mesh {

VertexAttributes::VertexAttributes(std::uint32_t width) : width_(width) {
    if (width_ > 0) chunks_.reset(new std::atomic<double*>[max_chunks]());
}

VertexAttributes::~VertexAttributes() { release(); }

VertexAttributes::VertexAttributes(VertexAttributes&& other) noexcept
    : width_(other.width_), chunks_(std::move(other.chunks_)), allocated_(other.allocated_.load()) {
    other.width_ = 0;
    other.allocated_ = 0;
}

VertexAttributes& VertexAttributes::operator=(VertexAttributes&& other) noexcept {
    if (this != &other) {
        release();
        width_ = other.width_;
        chunks_ = std::move(other.chunks_);
        allocated_ = other.allocated_.load();
        other.width_ = 0;
        other.allocated_ = 0;
    }
    return *this;
}

void VertexAttributes::release() {
    if (!chunks_) return;
    std::size_t left = allocated_.load(std::memory_order_relaxed);
    for (std::uint32_t c = 0; c < max_chunks && left > 0; ++c)
        if (double* chunk = chunks_[c].exchange(nullptr)) {
            std::free(chunk);
            --left;
        }
    allocated_ = 0;
}

std::span<double> VertexAttributes::write(VertexId v) {
    const std::uint32_t i = index(v);
    std::atomic<double*>& slot = chunks_[i >> chunk_bits];
    double* chunk = slot.load(std::memory_order_acquire);
    if (chunk == nullptr) {
        // The first thread to publish the chunk wins; the others free theirs.
        double* fresh =
            static_cast<double*>(std::calloc(std::size_t{chunk_size} * width_, sizeof(double)));
        if (fresh == nullptr) throw std::bad_alloc();
        if (slot.compare_exchange_strong(chunk, fresh, std::memory_order_acq_rel)) {
            allocated_.fetch_add(1, std::memory_order_relaxed);
            chunk = fresh;
        } else {
            std::free(fresh);
        }
    }
    return {chunk + std::size_t{i & (chunk_size - 1)} * width_, width_};
}

std::size_t VertexAttributes::bytes() const {
    return allocated_.load(std::memory_order_relaxed) * std::size_t{chunk_size} * width_ *
           sizeof(double);
}

void interpolate_on_segment(Mesh& mesh, VertexId v, VertexId from, VertexId to, double t) {
    VertexAttributes& table = mesh.attributes();
    if (table.width() == 0) return;
    const std::span<double> out = table.write(v);
    const std::span<const double> a = table.row(from), b = table.row(to);
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = (1 - t) * a[i] + t * b[i];
}

void interpolate_in_triangle(Mesh& mesh, VertexId v, const VertexId (&corners)[3]) {
    VertexAttributes& table = mesh.attributes();
    if (table.width() == 0) return;
    const auto& p = mesh.point(v);
    const auto& a = mesh.point(corners[0]);
    const auto& b = mesh.point(corners[1]);
    const auto& c = mesh.point(corners[2]);
    const double det = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    const double wb = ((p.x - a.x) * (c.y - a.y) - (c.x - a.x) * (p.y - a.y)) / det;
    const double wc = ((b.x - a.x) * (p.y - a.y) - (p.x - a.x) * (b.y - a.y)) / det;
    const std::span<double> out = table.write(v);
    const std::span<const double> ra = table.row(corners[0]), rb = table.row(corners[1]),
                                  rc = table.row(corners[2]);
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = (1 - wb - wc) * ra[i] + wb * rb[i] + wc * rc[i];
}

}  // namespace gpdr::mesh
