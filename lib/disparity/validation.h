#pragma once

#include <opencv2/core.hpp>

#include "disparity/sad_matcher.h"
#include "rig/camera_rig.h"

namespace stereonav {

// The validation tests of paper section 2.2. Each marks rejected pixels kInvalidDisparity in
// place; each is tuned by one threshold, trading quantity of data for quality. Each tests the
// pixels of `rows` only (all by default) and writes nothing else, so that stripes of rows can be
// tested in parallel.

// Mean of |Laplacian of Gaussian| of the reference image over a window x window square, in grey
// levels: low in untextured patches, whose matches are ambiguous. `texture` is reused if it
// already has the right size.
void textureMap(const cv::Mat1b& reference, int window, double sigma, cv::Mat1f& texture);

// "Sufficient texture" test: rejects pixels whose texture (textureMap) is not above `threshold`.
void rejectLowTexture(cv::Mat1f& disparity, const cv::Mat1f& texture, double threshold,
                      const cv::Range& rows = cv::Range::all());

// "Quality of match" test: rejects pixels whose best score divided by the sum of all candidate
// scores is not below `threshold` (a flat score curve, typical of occlusions and repetition).
void rejectAmbiguousMatches(cv::Mat1f& disparity, const SadMatch& match, double threshold,
                            const cv::Range& rows = cv::Range::all());

// Distinctiveness test: rejects pixels whose best score divided by the runner-up's
// (SadMatch::second_score, candidates more than one disparity from the best) is not below `ratio`.
// Unlike the quality-of-match ratio, its meaning does not depend on the number of candidates.
void rejectIndistinctMatches(cv::Mat1f& disparity, const SadMatch& match, double ratio,
                             const cv::Range& rows = cv::Range::all());

// Left-right consistency: `swapped` is the disparity image matched with `first` camera as the
// reference (swapReferenceWithFirstSecondary). A pixel at disparity d is kept only if the pixel
// it matches in that camera, at (x - bx*d, y - by*d) rounded, found a disparity within
// `max_difference` of d. Pixels whose match lies where the swapped search cannot see every
// candidate (within max_disparity of that camera's far border) are rejected too.
void rejectInconsistentMatches(cv::Mat1f& disparity, const cv::Mat1f& swapped, const SecondaryCamera& first,
                               double max_difference, const cv::Range& rows = cv::Range::all());

// Depth-edge test: a window straddling a depth edge is matched at the nearer surface's disparity,
// so the near surface spreads up to half a window over the far one beside it (foreground
// fattening) and every obstacle reads that much wider in the stereo scan, a door that much
// narrower. Along each row, where the disparity falls by at least `min_jump` from one valid pixel
// to the next (no farther apart than the window plus the jump: the occluded pixels a left-right
// check rejects lie between), the surfaces' true boundary is taken to be the strongest vertical
// brightness step of `reference` (mean over three rows) between half a window inside the near
// side and the far side's pixel; near-surface pixels beyond it are rejected. A step weaker than
// `min_step` grey levels says nothing, and the jump is left as it is. A near surface narrower than
// two windows (a pole, a table leg) is left fattened: its few pixels' steps cannot be told from
// its texture's, and trimming them could take the whole surface away.
void rejectFattenedEdges(cv::Mat1f& disparity, const cv::Mat1b& reference, int window, double min_jump,
                         double min_step, const cv::Range& rows = cv::Range::all());

}  // namespace stereonav
