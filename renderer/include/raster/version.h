// The render version: which pictures this library draws.
#pragma once

namespace raster {

/// Raised by one whenever any render's bytes change (a pixel of any image, or its PNG encoding), and only
/// then. It names the pictures, not the release: rasterd's ETags and `rasterd --version` carry it, so a
/// cache that holds a tag from another render version never gets a 304 for a picture that now looks
/// different. tests/render_versions.inc ties each version to a digest of the golden images (the examples'
/// pixels and PNG bytes); Render.GoldensBelongToTheRenderVersion fails when they change and this does not.
inline constexpr int kRenderVersion = 4;

}  // namespace raster
