using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// How each trainer's loader maps a light direction to its environment map, written from its code (commits and lines
    /// in Documentation~/maintainers/relighting.md), so that lights.json's conversions can be tested against them. Every
    /// direction is FROM the surface TOWARDS the light. TensoIR, NeRFactor and R3DG share lights.json's convention
    /// (<see cref="Equirect"/>); Stanford-ORB's is a quarter turn of columns away in a Y-up frame.
    /// </summary>
    public static class LightConventions
    {
        /// <summary>
        /// TensoIR's Environment_Light.get_light (models/relight_utils.py): phi = arccos(z) − 1e-6, theta = atan2(y, x),
        /// grid_sample at (−theta/π, 2·phi/π − 1); returned here as (u, v) = ((x + 1)/2, (y + 1)/2). R3DG's
        /// EnvLight.direct_light (scene/envmap.py) is the same code.
        /// </summary>
        public static void TensoIrUv(Vector3d d, out double u, out double v)
        {
            var n = d.Normalized();
            var phi = Math.Acos(Math.Max(-1, Math.Min(1, n.Z))) - 1e-6;
            var theta = Math.Atan2(n.Y, n.X);
            double queryX = -theta / Math.PI, queryY = phi / Math.PI * 2 - 1;
            u = (queryX + 1) / 2;
            v = (queryY + 1) / 2;
        }

        /// <summary>
        /// TensoIR's rotated lights (models/tensorBase_rotated_lights.py): the map is looked up at d·R(θ) for the row vector
        /// d, R = [[cos, −sin, 0], [sin, cos, 0], [0, 0, 1]]: that is Rz(−θ)·d, so its light_rotation θ is ours.
        /// </summary>
        public static Vector3d TensoIrRotatedLookup(Vector3d d, double degrees)
        {
            var a = degrees / 180 * Math.PI;
            double c = Math.Cos(a), s = Math.Sin(a);
            // (row vector) [x y z] · [[c, −s, 0], [s, c, 0], [0, 0, 1]] = [x·c + y·s, −x·s + y·c, z]
            return new Vector3d(d.X * c + d.Y * s, -d.X * s + d.Y * c, d.Z);
        }

        /// <summary>
        /// NeRFactor's gen_light_xyz (brdf/renderer.py) with xiuminglib's sph2cart: the direction of light pixel (row i,
        /// column j) of an h×w map: lat = π/2 − (i + 1)·π/(h + 2), lng = π − (j + 1)·2π/(w + 2) (the poles left out),
        /// (cos lat cos lng, cos lat sin lng, sin lat).
        /// </summary>
        public static Vector3d NerfactorDirection(int row, int column, int height, int width)
        {
            double latStep = Math.PI / (height + 2), lngStep = 2 * Math.PI / (width + 2);
            // np.linspace(π/2 − step, −π/2 + step, h): from the first to the last over h − 1 intervals.
            var lat = height == 1 ? Math.PI / 2 - latStep : (Math.PI / 2 - latStep) - row * ((Math.PI - 2 * latStep) / (height - 1));
            var lng = width == 1 ? Math.PI - lngStep : (Math.PI - lngStep) - column * ((2 * Math.PI - 2 * lngStep) / (width - 1));
            return new Vector3d(Math.Cos(lat) * Math.Cos(lng), Math.Cos(lat) * Math.Sin(lng), Math.Sin(lat));
        }

        /// <summary>NeRFactor's (lat, lng) of a direction, the inverse of its sph2cart.</summary>
        public static void NerfactorLatLng(Vector3d d, out double lat, out double lng)
        {
            var n = d.Normalized();
            lat = Math.Asin(Math.Max(-1, Math.Min(1, n.Z)));
            lng = Math.Atan2(n.Y, n.X);
        }

        /// <summary>
        /// Stanford-ORB's own convention ("ours" in orb/utils/env_map.py, env_map_to_cam_to_world_by_convention): for a
        /// Y-up direction (x, y, z), column = (atan2(x, −z) + π)/2π and row = acos(y)/π (of W − 1 and H − 1), +Z at the
        /// left, +Y at the top. Our output world goes to that Y-up frame as (x, y, z) = (x, z, −y) of ours (Blender to
        /// OpenGL axes), which makes ORB's u ours + 0.25: the ORB map is ours with its columns rolled right by W/4.
        /// </summary>
        public static void StanfordOrbUv(Vector3d output, out double u, out double v)
        {
            var n = output.Normalized();
            double x = n.X, y = n.Z, z = -n.Y;
            u = (Math.Atan2(x, -z) + Math.PI) / (2 * Math.PI);
            if (u >= 1) u -= 1;
            v = Math.Acos(Math.Max(-1, Math.Min(1, y))) / Math.PI;
        }

        /// <summary>The output-world direction of Stanford-ORB's (u, v): the inverse of <see cref="StanfordOrbUv"/>.</summary>
        public static Vector3d StanfordOrbDirection(double u, double v)
        {
            // ORB's own meshgrid: theta = u·2π − π/2, phi = v·π, (−cos θ sin φ, cos φ, −sin θ sin φ) in its Y-up frame.
            double theta = u * 2 * Math.PI - 0.5 * Math.PI, phi = v * Math.PI;
            double x = -Math.Cos(theta) * Math.Sin(phi), y = Math.Cos(phi), z = -Math.Sin(theta) * Math.Sin(phi);
            return new Vector3d(x, -z, y);
        }

        /// <summary>Stanford-ORB's columns roll: ORB column c shows our column (c − W/4) mod W.</summary>
        public static int StanfordOrbRollColumns(int width) => width / 4;
    }
}
