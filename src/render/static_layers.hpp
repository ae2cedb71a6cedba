// The layers of an animation's frames that read nothing of the frame: drawn
// once and copied into every other frame.
//
// A frame of an animation draws every layer of the figure (render/
// panel_drawing.hpp, FrameSelection): the layers that move (the pattern, the
// shapes carried) at the frame's time, and every other as in the static
// figure. The others cost as much at each frame as in the figure: an
// analysis printed in a label (the ARA of SAM Fig. 2), a table of properties
// (Fig. 10), a plot. A layer whose drawing never asked for the frame's
// selection is the same at every frame of the same motions, by construction:
// the panel builders hand the selection out through one accessor that
// notes each read, and a layer drawn without one is recorded here and copied
// into the later frames instead of being drawn again.
//
// Safe to share between the threads that draw the frames of one animation: a
// part, once recorded, is never changed or removed.
#pragma once

#include <cstddef>
#include <map>
#include <mutex>
#include <utility>
#include <vector>

#include "render/drawing.hpp"
#include "render/projection.hpp"

namespace pita::render {

// One layer's share of a panel's drawing.
struct LayerPart {
  std::vector<Item> items;
  std::vector<Legend> legends;
};

// How a panel of space is seen (render/pose_panel.hpp): the camera, which
// "auto" turns after looking at the motion's samples, and the ground its
// shadows fall on. It reads nothing of the frame either: chosen once.
struct SpaceView {
  Projection projection;
  double ground = 0.0;
};

class StaticLayers {
 public:
  // The part of layer `layer` of panel `panel`, once recorded; null before.
  const LayerPart* find(std::size_t panel, std::size_t layer) const {
    const std::lock_guard lock(mutex_);
    const auto found = parts_.find({panel, layer});
    return found == parts_.end() ? nullptr : &found->second;
  }

  // Records what the layer drew: the items and legends of `drawing` from
  // `items_from` and `legends_from` on. A part recorded already stays.
  void record(std::size_t panel, std::size_t layer, const Drawing& drawing, std::size_t items_from,
              std::size_t legends_from) {
    LayerPart part{{drawing.items.begin() + static_cast<std::ptrdiff_t>(items_from), drawing.items.end()},
                   {drawing.legends.begin() + static_cast<std::ptrdiff_t>(legends_from), drawing.legends.end()}};
    const std::lock_guard lock(mutex_);
    parts_.try_emplace({panel, layer}, std::move(part));
  }

  // Panel `panel`'s view in space, once recorded; null before.
  const SpaceView* view(std::size_t panel) const {
    const std::lock_guard lock(mutex_);
    const auto found = views_.find(panel);
    return found == views_.end() ? nullptr : &found->second;
  }
  void record_view(std::size_t panel, const SpaceView& view) {
    const std::lock_guard lock(mutex_);
    views_.try_emplace(panel, view);
  }

 private:
  mutable std::mutex mutex_;
  std::map<std::pair<std::size_t, std::size_t>, LayerPart> parts_;
  std::map<std::size_t, SpaceView> views_;
};

// Draws layer `layer` of panel `panel` into `drawing`: copied from `cache`
// when it holds the layer, else by `draw()`, which appends the layer's items
// and legends and returns whether the layer may differ between frames (it
// read the frame's selection, or left something outside `drawing`). A layer
// that may not is recorded. A null cache draws every layer.
template <class Draw>
void draw_layer(StaticLayers* cache, std::size_t panel, std::size_t layer, Drawing& drawing, Draw&& draw) {
  if (cache != nullptr) {
    if (const LayerPart* part = cache->find(panel, layer)) {
      drawing.items.insert(drawing.items.end(), part->items.begin(), part->items.end());
      drawing.legends.insert(drawing.legends.end(), part->legends.begin(), part->legends.end());
      return;
    }
  }
  const std::size_t items = drawing.items.size();
  const std::size_t legends = drawing.legends.size();
  const bool varies = draw();
  if (cache != nullptr && !varies) cache->record(panel, layer, drawing, items, legends);
}

}  // namespace pita::render
