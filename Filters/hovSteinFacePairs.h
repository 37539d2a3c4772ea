/**
 * @file hovSteinFacePairs.h
 * @brief The per-view data of the boundary faces of the Stein sort's pair
 *        search (hovSteinBoundaryPairs.h) and the tests on one (EXIT face F,
 *        ENTRY face G) pair: which need their cells' Obstructs() test, which
 *        need none, and which give the edge without it.
 *
 * Screen points, extents and depths are the view's projected doubles
 * (View::Proj), in which the whole sort reasons; the screen tests keep a
 * margin on their safe side: 1e-9 of the faces' extents (1e-4 to prove an
 * edge) plus 1e-9 of the magnitude the projection's rounding is relative to
 * (FaceData::ScreenScale), far above that rounding.
 */
#ifndef hovSteinFacePairs_h
#define hovSteinFacePairs_h

#include "hovSteinBoundaryPairs.h" // ViewFace
#include "hovSteinPairGrid.h"      // FaceData
#include "hovSteinView.h"          // Geometry, View

namespace hovStein
{
/// The face data of @p vf in view @p v (faces of cells cut by the near plane
/// get their cell's visible extents and depths, and Screen = 0).
void FillFaceData(const Geometry& g, const View& v, const ViewFace& vf, FaceData& d);

/**
 * Some corner of @p other lies on the outer side of the plane of the exact face
 * @p d, or within a margin inside it (true if @p d is not exact). The margin,
 * 1e-9 times the coordinate magnitude (100x the rounding tolerance of
 * Obstructs()), keeps nearly coplanar non-conforming interfaces whose points
 * are not exactly coplanar (sheared sliding interfaces) among the candidates.
 */
bool SomeCornerOutside(const Geometry& g, const FaceData& d, const FaceData& other);

/**
 * The screen projections of the triangles @p d and @p e clearly apart: an
 * edge of one with every corner of the other outside its line by more than
 * the margin (then no ray meets both). False for other faces and for faces of
 * cells cut by the near plane.
 */
bool ApartOnScreen(const FaceData& d, const FaceData& e);

/**
 * An open set of view rays leaves a cell through the EXIT face @p f and later
 * enters another through the ENTRY face @p e, so that f's cell must be drawn
 * after e's (some ray meets it first; in a mesh of disjoint convex cells none
 * meets them in the other order, and the overlap, a disc of 1e-4 of the
 * extents, is far above what Obstructs() treats as touching, so Obstructs()
 * holds as well): both triangles of visible cells with exact planes (the eye
 * strictly inside f's, strictly outside e's), @p fAfter = DepthAfter(f's
 * rear) < @p eBefore = DepthBefore(e's front), and a point inside both by
 * more than the margin (tried: the centroids, their midpoint, the centre of
 * the extents' overlap, the area centroid of the triangles' intersection).
 * A triangle whose edges disagree on its orientation (a sliver of
 * rounding-level area) proves nothing. False when it cannot tell.
 */
bool InFrontOnScreen(const FaceData& f, double fAfter, const FaceData& e, double eBefore);

/// What ClassifyFacePair() makes of a face pair.
enum FacePairKind
{
  NoCandidate = -1, ///< no ray passes F and then G (ApartOnScreen, SomeCornerOutside)
  NeedsTest = 0,    ///< the cells' Obstructs() decides
  ProvedEdge = 1    ///< InFrontOnScreen (if @p certify)
};

/**
 * The tests on the EXIT face @p f (DepthAfter of its rear @p fAfter) and the
 * ENTRY face @p e (DepthBefore of its front @p eBefore): NoCandidate if
 * ApartOnScreen(), else ProvedEdge if @p certify and InFrontOnScreen(), else
 * as SomeCornerOutside() both ways. A proved pair has a corner of each face
 * beyond the other's plane (rays pass f, then e), so SomeCornerOutside() is
 * asked only for the others. The six screen lines are set up once, and the
 * proof's first four points are tried before the apart test (a proof
 * excludes it; those points prove 38.5% of the 0.5M heatsink's face pairs).
 */
int ClassifyFacePair(const Geometry& g, const FaceData& f, double fAfter, const FaceData& e,
  double eBefore, bool certify);
}

#endif
