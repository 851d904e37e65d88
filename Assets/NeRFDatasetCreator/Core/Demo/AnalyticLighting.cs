using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The analytic scene under a relighting condition (<see cref="LightingCondition"/>): Lambert shading of the diffuse colour
    /// (the base colour <see cref="AnalyticScene.ColourOf"/>, read as linear, × (1 − <see cref="AnalyticMaterials.Metallic"/>):
    /// no specular lobe), outgoing = albedo / π · E. An environment's
    /// irradiance E(n) = ∫ L(ω) max(0, n·ω) dω is integrated numerically over the map's pixels (solid angle
    /// (2π/W)(π/H) sin θ each) into a table of normals, without shadows — as Unity's rasterised relight (SH ambient and a
    /// reflection probe) has none; a point or spot light gives E = I · colour · max(0, n·l) / r², zero where a traced
    /// shadow ray meets the scene first (with <c>shadows</c>) or, for a spot, outside its cone.
    /// </summary>
    public static class AnalyticLighting
    {
        /// <summary>The normals table's width (height half of it).</summary>
        public const int IrradianceWidth = 64;

        /// <summary>The shading of every key of <paramref name="settings"/>' relighting for <paramref name="scene"/>.</summary>
        public static Dictionary<string, AnalyticDataset.SurfaceShading> For(DatasetSettings settings, AnalyticScene scene, IReadOnlyDictionary<string, EnvironmentMap> environments)
        {
            var shadings = new Dictionary<string, AnalyticDataset.SurfaceShading>(StringComparer.Ordinal);
            if (settings.Relighting == null || !settings.Relighting.Enabled) return shadings;
            foreach (var c in settings.Relighting.Conditions)
            {
                if (c.Kind == LightingKind.Environment)
                {
                    var irradiance = Irradiance(environments[c.Name], IrradianceWidth);
                    foreach (var rotation in c.Rotations)
                        shadings[LightingKeys.Environment(c.Name, rotation)] = Environment(irradiance, rotation, c.Intensity);
                }
                else shadings[c.Name] = Local(c, scene);
            }
            return shadings;
        }

        /// <summary>E(n) for the normal through each pixel centre of a W × W/2 table (<see cref="Equirect"/>), RGB.</summary>
        public static EnvironmentMap Irradiance(EnvironmentMap map, int width)
        {
            int height = width / 2, w = map.Width, h = map.Height;
            var directions = new Vector3d[w * h];
            var solidAngles = new double[h];
            for (var row = 0; row < h; row++)
            {
                solidAngles[row] = 2 * Math.PI / w * (Math.PI / h) * Math.Sin((row + 0.5) / h * Math.PI);
                for (var column = 0; column < w; column++) directions[row * w + column] = Equirect.PixelDirection(column, row, w, h);
            }
            var rgb = new float[width * height * 3];
            for (var row = 0; row < height; row++)
                for (var column = 0; column < width; column++)
                {
                    var n = Equirect.PixelDirection(column, row, width, height);
                    double r = 0, g = 0, b = 0;
                    for (var i = 0; i < directions.Length; i++)
                    {
                        var cos = Vector3d.Dot(n, directions[i]);
                        if (cos <= 0) continue;
                        var weight = cos * solidAngles[i / w];
                        r += map.Rgb[i * 3] * weight;
                        g += map.Rgb[i * 3 + 1] * weight;
                        b += map.Rgb[i * 3 + 2] * weight;
                    }
                    var at = (row * width + column) * 3;
                    rgb[at] = (float)r;
                    rgb[at + 1] = (float)g;
                    rgb[at + 2] = (float)b;
                }
            return new EnvironmentMap(width, height, rgb);
        }

        /// <summary>Lambert under the environment whose irradiance table is <paramref name="irradiance"/>, rotated by <paramref name="degrees"/>.</summary>
        public static AnalyticDataset.SurfaceShading Environment(EnvironmentMap irradiance, double degrees, double intensity)
        {
            return (point, normal, albedo, result) =>
            {
                // The rotated map's light from n arrived from Rz(−θ)·n: EnvironmentMap.Radiance(d, θ).
                irradiance.Radiance(normal, degrees, result);
                for (var c = 0; c < 3; c++) result[c] = albedo[c] / Math.PI * result[c] * intensity;
            };
        }

        static AnalyticDataset.SurfaceShading Local(LightingCondition c, AnalyticScene scene)
        {
            var position = new Vector3d(c.Position[0], c.Position[1], c.Position[2]);
            var spot = c.Kind == LightingKind.Spot ? LightGeometry.SpotDirection(c) : null;
            var axis = spot == null ? Vector3d.Zero : new Vector3d(spot[0], spot[1], spot[2]);
            var cosCone = Math.Cos(c.SpotAngle / 2 * Math.PI / 180);
            return (point, normal, albedo, result) =>
            {
                var toLight = position - point;
                var distance = toLight.Length;
                var l = toLight / distance;
                var cos = Vector3d.Dot(normal, l);
                var lit = cos > 0 && (spot == null || Vector3d.Dot(-l, axis) >= cosCone);
                // The shadow ray starts a little off the surface, along the normal, so it does not hit its own point.
                if (lit && c.Shadows && scene.Trace(point + normal * 1e-6, l, 1e-6, out var t, out _, out _, out var alpha) && t < distance && alpha >= 1) lit = false;
                var e = lit ? c.Intensity * cos / (distance * distance) : 0;
                for (var k = 0; k < 3; k++) result[k] = albedo[k] / Math.PI * c.Colour[k] * e;
            };
        }
    }
}
