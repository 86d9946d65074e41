/*---------------------------------------------------------------------------*\
 hsrod calibration, immersed spheres: the cells each sphere covers (solid
 fraction, linear-wall coefficient) and the rigid-body velocity field U_s.
\*---------------------------------------------------------------------------*/
#include "immersedSpheres.H"
#include "vec3Conversion.H"

#include <cmath>

using namespace Foam;

namespace hsrodFoam
{

void immersedSpheres::markSphere(std::size_t k)
{
    const auto& s = spheres_.spheres()[k];
    const point X(s.x[0], s.x[1], s.x[2]);
    const scalar r = s.radius();
    auto& marks = marks_[k];
    marks.clear();

    const bool smooth = (alphaModel_ == "smoothed");
    const vectorField& C = mesh_.C().primitiveField();

    forAll(cellBb_, celli)
    {
        const boundBox& b = cellBb_[celli];
        const scalar band = smooth ? 0.5*smoothWidth_*cellH_[celli] : 0;
        // quick reject: sphere grown by the smoothing band / one cell misses the cell box
        const point nearest = b.nearest(X);
        const vector span = b.max() - b.min();
        const scalar reach = max(band, cmptMax(span));
        if (magSqr(nearest - X) >= sqr(r + reach)) continue;

        // linear-wall coefficient g [1/m^2] (see header): centre inside -> GREAT;
        // centre at distance s0 outside -> sum_i max(0, |n_i| h_i - s0)/(h_i^2 s0)
        scalar g = 0;
        {
            const vector rc = C[celli] - X;
            const scalar dist = mag(rc);
            const scalar s0 = dist - r;
            if (s0 <= 0)
            {
                g = GREAT;
            }
            else
            {
                const vector n = rc/dist;
                for (direction i = 0; i < 3; ++i)
                {
                    const scalar hi = span[i];
                    const scalar gap = mag(n[i])*hi - s0;
                    if (gap > 0) g += gap/(hi*hi*s0);
                }
            }
        }

        scalar a = 0;
        if (smooth)
        {
            // cosine ramp of the signed distance s over a width w = smoothWidth h
            const scalar sd = mag(C[celli] - X) - r;
            const scalar w = 2*band;
            if (sd <= -band) a = 1;
            else if (sd >= band) a = 0;
            else a = 0.5*(1 - std::sin(constant::mathematical::pi*sd/w));
        }
        else
        {
            // farthest box corner inside the sphere: the cell is solid
            const point& lo = b.min();
            const point& hi = b.max();
            vector far;
            for (direction i = 0; i < 3; ++i)
            {
                far[i] = max(mag(lo[i] - X[i]), mag(hi[i] - X[i]));
            }
            if (magSqr(far) <= r*r)
            {
                a = 1;
            }
            else
            {
                // n^3 midpoint samples of the cell box (exact for the
                // axis-aligned hexahedra of blockMesh/refineMesh meshes)
                label in = 0;
                const vector box = hi - lo;
                for (label i = 0; i < nSub_; ++i)
                for (label j = 0; j < nSub_; ++j)
                for (label l = 0; l < nSub_; ++l)
                {
                    const point q
                    (
                        lo.x() + (i + 0.5)*box.x()/nSub_,
                        lo.y() + (j + 0.5)*box.y()/nSub_,
                        lo.z() + (l + 0.5)*box.z()/nSub_
                    );
                    if (magSqr(q - X) < r*r) ++in;
                }
                a = scalar(in)/pow3(scalar(nSub_));
            }
        }
        if (a > 0 || g > 0) marks.push_back({celli, a, g});
    }
}


void immersedSpheres::updateBodies(scalar t)
{
    spheres_.set_time(t);
    if (marks_.size() != spheres_.size()) marks_.resize(spheres_.size());

    scalarField& aSum = alphaSum_.primitiveFieldRef();
    scalarField& wSum = weightSum_.primitiveFieldRef();
    scalarField& gSum = geomSum_.primitiveFieldRef();
    vectorField& us = Us_.primitiveFieldRef();
    aSum = 0;
    wSum = 0;
    gSum = 0;
    us = Zero;
    const bool linear = (forcing_ == "linearWall");
    const vectorField& C = mesh_.C().primitiveField();

    for (std::size_t k = 0; k < spheres_.size(); ++k)
    {
        markSphere(k);
        const auto& s = spheres_.spheres()[k];
        for (auto& m : marks_[k])
        {
            // weight of sphere k in this cell: its coefficient (capped) or its fraction
            m.w = linear ? min(m.g, 1e30) : m.alpha;
            aSum[m.cell] += m.alpha;
            gSum[m.cell] = min(gSum[m.cell] + m.g, GREAT);
            wSum[m.cell] += m.w;
            us[m.cell] += m.w*toVec(s.rigid_velocity(toArr(C[m.cell])));
        }
    }
    forAll(wSum, celli)
    {
        if (wSum[celli] > 0) us[celli] /= wSum[celli];
    }
    alpha_.primitiveFieldRef() = min(aSum, scalar(1));
    alpha_.correctBoundaryConditions();
    alphaSum_.correctBoundaryConditions();
    Us_.correctBoundaryConditions();
}

} // namespace hsrodFoam
