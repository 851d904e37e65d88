using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The camera JSON of Nerfies, HyperNeRF, DyCheck and 4DGaussians' HyperNeRF reader, one file per image. Every
    /// reader builds its camera from the same keys (google/nerfies 1a38512 nerfies/camera.py:140–160 Camera.from_json;
    /// KAIR-BAIR/dycheck ddf77a4 dycheck/geometry/camera.py:306–326; hustvl/4DGaussians 843d5ac scene/hyper_loader.py:90):
    /// <list type="bullet">
    /// <item><c>orientation</c>: the world-to-camera rotation in OpenCV axes (x right, y down, looking along +z): its
    /// rows are the camera's axes in the world — <c>optical_axis = orientation[2, :]</c> (camera.py:217–219),
    /// <c>points_to_local_points = orientation·(p − position)</c> (lines 279–282). From our camera-to-world (OpenGL axes:
    /// y up, looking along −z): row 0 = +x column, row 1 = −y column, row 2 = −z column.</item>
    /// <item><c>position</c>: the camera centre in the world (before scene.json's centre and scale, nerfies/datasets/core.py:102–105).</item>
    /// <item><c>focal_length</c> = fx in pixels, <c>pixel_aspect_ratio</c> = fy / fx (camera.py:181–187),
    /// <c>principal_point</c> = (cx, cy) in continuous pixels with pixel centres at i + ½ (get_pixel_centers,
    /// lines 317–321) — the same convention as ours, so (cx, cy) is written as is; <c>skew</c> 0; no distortion;
    /// <c>image_size</c> = [W, H] (lines 205–215).</item>
    /// </list>
    /// </summary>
    public static class NerfiesCamera
    {
        /// <summary>The camera JSON of a view at <paramref name="cameraToWorld"/> (Blender world, OpenGL axes) with <paramref name="intrinsics"/>.</summary>
        public static JObject Json(Matrix4x4d cameraToWorld, CameraIntrinsics intrinsics)
        {
            var x = cameraToWorld.Column(0);
            var y = -cameraToWorld.Column(1);
            var z = -cameraToWorld.Column(2);
            var c = cameraToWorld.Translation;
            return new JObject
            {
                ["orientation"] = new JArray(Row(x), Row(y), Row(z)),
                ["position"] = Row(c),
                ["focal_length"] = intrinsics.FlX,
                ["principal_point"] = new JArray(intrinsics.Cx, intrinsics.Cy),
                ["skew"] = 0.0,
                ["pixel_aspect_ratio"] = intrinsics.FlY / intrinsics.FlX,
                ["radial_distortion"] = new JArray(0.0, 0.0, 0.0),
                ["tangential_distortion"] = new JArray(0.0, 0.0),
                ["image_size"] = new JArray(intrinsics.Width, intrinsics.Height),
            };
        }

        static JArray Row(Vector3d v) => new JArray(v.X, v.Y, v.Z);
    }
}
