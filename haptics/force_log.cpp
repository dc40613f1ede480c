#include "haptics/force_log.h"

#include <cstdio>
#include <ostream>

#include <glm/geometric.hpp>

#include "gen/util/atomic_file.h"
#include "haptics/force_model.h"

namespace tsf::haptics {

void writeForceLogCsv(const std::string& path, const ForceLog& log) {
    writeFileAtomically(path, [&](std::ostream& os) {
        os << "t_s,x_m,y_m,z_m,fx_N,fy_N,fz_N,force_N,buttons,mode,lod,contact,sliding,clamped,damping,"
              "penetration_mm\n";
        char line[320];
        for (size_t i = 0; i < log.size(); ++i) {
            const LogRecord& r = log[i];
            const int n = std::snprintf(
                line, sizeof line, "%.6f,%.7f,%.7f,%.7f,%.5f,%.5f,%.5f,%.5f,%u,%s,%.3f,%d,%d,%d,%d,%.4f\n", r.t_s,
                r.position_m.x, r.position_m.y, r.position_m.z, r.force_N.x, r.force_N.y, r.force_N.z,
                glm::length(r.force_N), r.buttons, r.volume ? "volume" : "surface", double(r.lod),
                (r.flags & kFlagContact) ? 1 : 0, (r.flags & kFlagSliding) ? 1 : 0, (r.flags & kFlagClamped) ? 1 : 0,
                (r.flags & kFlagDamping) ? 1 : 0, double(r.penetration_m) * 1000.0);
            os.write(line, n);
        }
    });
}

}  // namespace tsf::haptics
