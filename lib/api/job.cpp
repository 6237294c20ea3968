#include <gpdr/errors.hpp>
#include <gpdr/job.hpp>

namespace gpdr {
JobResult run_job(const Options&, const WarningSink&) { throw NotImplemented("meshing is not implemented yet"); }
}  // namespace gpdr
