// What this version of gpdr does not do yet.  Each refusal names the switch,
// so a Triangle command line that needs a later feature fails loudly instead
// of producing a different mesh.

#include <gpdr/errors.hpp>

#include "api/job_stages.hpp"

namespace gpdr::api {

void refuse_unimplemented(const Options& o) {
    const auto refuse = [](const char* what) {
        throw NotImplemented(std::string(what) + " is not implemented yet in this version of gpdr");
    };
    if (o.threads > 1 && wants_refinement(o)) refuse("-jN with N > 1 (parallel refinement)");
    // On a point set without -p or -r, as in Triangle: -A and -O do nothing
    // (regions and holes come from a .poly); -D does nothing (a Delaunay
    // triangulation already conforms); -Y, -S, -s, -gN and -PN matter only
    // when refining, and refinement takes them.
}

}  // namespace gpdr::api
