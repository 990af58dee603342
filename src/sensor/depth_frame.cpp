// One depth-camera frame: render, metric depth, the sensor model, range.
#include <zraster/depth_camera.hpp>

namespace zraster {

DepthFrame render_depth_frame(const Scene& scene, const RenderOptions& options,
                              const std::optional<StructuredLightSensor>& sensor) {
    if (sensor) check_sensor(*sensor);  // before the frame is drawn
    RenderOptions o = options;
    o.normal_target = true;
    RenderResult result = render(scene, o);
    RenderTargets& t = result.targets;
    DepthFrame frame;
    frame.width = t.width;
    frame.height = t.height;
    frame.camera = result.stats.camera;
    frame.z.resize(t.depth.size());
    metric_depth(frame.camera, depth_clear_value(o), t.depth, frame.z);
    if (sensor) {
        o.camera = frame.camera;
        std::vector<MeshView> meshes;
        std::vector<InstanceView> instances;
        frame.sensor_stats = apply_structured_light(*sensor, view_of(scene, meshes, instances), o,
                                                    frame.z, t.normal);
    }
    frame.range.resize(frame.z.size());
    range_from_z(frame.camera, frame.width, frame.height, frame.z, frame.range);
    frame.color = std::move(t.color);
    frame.normal = std::move(t.normal);
    return frame;
}

}  // namespace zraster
