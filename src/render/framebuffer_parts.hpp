#pragma once
// What the render stage's framebuffers are made of (offscreen_target.hpp, view_target.hpp,
// beam_pass.hpp): a 2-D texture of one size and format, and a depth-stencil renderbuffer
// attached to the framebuffer bound now (tile skipping marks tiles off in its stencil).
// Need a current GL context; the objects belong to it and the caller deletes them.
namespace zs {

// internalFormat, format and type as glTexImage2D takes them; `linear` filtering (a picture
// blitted at another size) or nearest.
unsigned newTexture2D(unsigned internalFormat, unsigned format, unsigned type, int width,
                      int height, bool linear = false);
// Depth and stencil come in one format everywhere (GL_DEPTH24_STENCIL8); returns the
// renderbuffer.
unsigned attachDepthStencil(int width, int height);

}  // namespace zs
