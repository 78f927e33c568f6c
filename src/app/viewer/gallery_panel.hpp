#pragma once
// The viewer's gallery window (the G key): a search box over the example surfaces and the
// list of those that match — a thumbnail of the gallery's picture where there is one, name,
// degree and the first sentence of each description (the whole description on hover). A click on an
// entry, or Enter in the search box (the first match), picks it; the viewer then shows it as the
// N/P keys would.
#include <string>
#include <vector>

#include "app/gallery.hpp"
#include "app/viewer/focus_request.hpp"
#include "app/viewer/gallery_thumbnails.hpp"

namespace zs::app {

struct GalleryPanel {
  bool visible = false;
  FocusRequest searchFocus;  // put the cursor in the search box
  std::string search;
  std::vector<GalleryEntry> entries;  // one per example, in the examples' order
  GalleryThumbnails thumbnails;       // of the entries that have a picture
};

// The index of the entry picked this frame, or -1. `current` is highlighted.
int drawGallery(GalleryPanel& gallery, int current);

}  // namespace zs::app
