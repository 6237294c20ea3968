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
    if (o.refine) refuse("-r (refining an existing mesh)");
    if (o.poly) refuse("-p (constrained Delaunay triangulation of a .poly file)");
    if (o.quality) refuse("-q (quality mesh refinement)");
    if (o.area_limit || o.regional_area) refuse("-a (area constraints)");
    if (o.user_test) refuse("-u (triunsuitable() area test)");
    if (!o.unsuitable_library.empty()) refuse("--unsuitable (loading triunsuitable() from a shared object)");
    // The switches below only change PSLG meshing or refinement, which the
    // checks above already refuse; without -p, -r or -q Triangle accepts them
    // and they have no effect on a point set, and so it is here:
    //   -A (needs -p), -O (holes come from .poly), -D, -Y, -S, -s (segments
    //   are split only when refining or conforming a PSLG), -jN, -gN, -PN and
    //   --threads, --granularity, --placement (refinement settings).
    // -D on a point set: the Delaunay triangulation is already conforming.
}

}  // namespace gpdr::api
