// Regression planes of binned points. See bin_regression.h.
#include "gen/field/bin_regression.h"

namespace tsf {
namespace {

struct Covariance {
    double xx = 0, xy = 0, yy = 0;
};

Covariance positionCovariance(const BinMoments& m) {
    const double n = double(m.n);
    return {m.sxx - m.sx * m.sx / n, m.sxy - m.sx * m.sy / n, m.syy - m.sy * m.sy / n};
}

}  // namespace

bool hasRegressionPlane(const BinMoments& m) {
    if (m.n < kMinRegressionPoints) return false;
    const Covariance c = positionCovariance(m);
    const double trace = c.xx + c.yy;
    const double det = c.xx * c.yy - c.xy * c.xy;
    return trace > 0 && det > kCollinearRelDet * trace * trace;
}

std::optional<PlaneSlope> densityRelativeSlope(const BinMoments& m) {
    if (!hasRegressionPlane(m)) return std::nullopt;
    const double n = double(m.n);
    return PlaneSlope{kDensitySlopePerPitch * m.sx / n, kDensitySlopePerPitch * m.sy / n};
}

std::optional<PlaneSlope> weightSlope(const BinMoments& m) {
    if (!hasRegressionPlane(m)) return std::nullopt;
    const double n = double(m.n);
    const Covariance c = positionCovariance(m);
    const double cxw = m.sxw - m.sx * m.sw / n, cyw = m.syw - m.sy * m.sw / n;
    const double det = c.xx * c.yy - c.xy * c.xy;
    // Normal equations of the centred fit: [xx xy; xy yy] (b, c) = (cxw, cyw).
    return PlaneSlope{(c.yy * cxw - c.xy * cyw) / det, (c.xx * cyw - c.xy * cxw) / det};
}

}  // namespace tsf
