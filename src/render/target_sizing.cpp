#include "render/target_sizing.hpp"

#include <cstddef>

#include "memory/huge_pages.hpp"

namespace zraster::detail {

WantedTargets wanted_targets(const RenderOptions& options) {
    return {.color = options.color_target,
            .normal = options.normal_target,
            .ids = options.id_targets,
            .coverage = options.coverage_counts};
}

TargetViews size_targets(RenderTargets& targets, const RenderOptions& options,
                         WantedTargets wanted) {
    const std::size_t pixels = std::size_t(options.width) * std::size_t(options.height);
    targets.width = options.width;
    targets.height = options.height;
    memory::resize_on_huge_pages(targets.depth, pixels);
    memory::resize_on_huge_pages(targets.color, wanted.color ? pixels * 4 : 0);
    memory::resize_on_huge_pages(targets.normal, wanted.normal ? pixels : 0);
    memory::resize_on_huge_pages(targets.instance_id, wanted.ids ? pixels : 0);
    memory::resize_on_huge_pages(targets.primitive_id, wanted.ids ? pixels : 0);
    targets.front_hits.resize(wanted.coverage ? pixels : 0);
    targets.back_hits.resize(wanted.coverage ? pixels : 0);
    return view_of(targets);
}

}  // namespace zraster::detail
