using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The Gaussian centres of a trained splat's PLY (graphdeco 3DGS's save_ply layout, which splatfacto's ns-export and
    /// gsplat's export_splats write too: a <c>vertex</c> element with x y z, opacity as a logit, scale_*, rot_*).
    /// Opacity is sigmoid(logit), as every renderer applies it.
    /// </summary>
    public sealed class GaussianPly
    {
        GaussianPly(List<Vector3d> centres, int total)
        {
            Centres = centres;
            Total = total;
        }

        /// <summary>The centres whose opacity exceeds the threshold asked for, in file order.</summary>
        public IReadOnlyList<Vector3d> Centres { get; }

        /// <summary>How many Gaussians the file holds.</summary>
        public int Total { get; }

        /// <summary>Whether the PLY at <paramref name="path"/> declares a Gaussian splat's vertex properties (opacity, scale_0, rot_0).</summary>
        public static bool IsGaussianSplat(string path)
        {
            if (!File.Exists(path) || !path.EndsWith(".ply", StringComparison.OrdinalIgnoreCase)) return false;
            using (var stream = ReadableFile.OpenRead(path, ReadableFile.MaxGeometryBytes))
            {
                var header = PlyHeader.Read(stream, 1 << 20, 10001);
                if (!header.Ended || header.Lines.Count == 0 || header.Lines[0] != "ply" || header.Declare() != null) return false;
                var vertex = header.Elements.FirstOrDefault(e => e.Name == "vertex");
                return vertex != null && new[] { "opacity", "scale_0", "rot_0" }.All(n => vertex.Properties.Any(p => p.Name == n && !p.IsList));
            }
        }

        /// <summary>The centres with sigmoid(opacity) &gt; <paramref name="minOpacity"/> (0 keeps every one).</summary>
        public static GaussianPly ReadCentres(string path, double minOpacity)
        {
            Exception Fail(string reason, string fix) => new InvalidParameterException(new[] { new ValidationProblem("PLY", path, reason, fix) });
            using (var stream = ReadableFile.OpenRead(path, ReadableFile.MaxGeometryBytes))
            {
                var header = PlyHeader.Read(stream, 1 << 20, 10001);
                if (!header.Ended || header.Lines.Count == 0 || header.Lines[0] != "ply" || header.Declare() != null) throw Fail("is not a readable PLY file.", "Pass the trainer's point_cloud.ply / splat.ply.");
                var vertex = header.Elements.FirstOrDefault(e => e.Name == "vertex");
                int Index(string name) => vertex?.Properties.FindIndex(p => p.Name == name && !p.IsList) ?? -1;
                int ix = Index("x"), iy = Index("y"), iz = Index("z"), io = Index("opacity");
                if (vertex == null || ix < 0 || iy < 0 || iz < 0 || io < 0)
                    throw Fail("has no vertex x, y, z and opacity: it is not a Gaussian splat.", "Pass the PLY a Gaussian splatting trainer saved (3DGS point_cloud.ply, ns-export's splat.ply, gsplat's ply/point_cloud_<step>.ply).");
                if (vertex.Count > int.MaxValue / 4) throw Fail("has " + vertex.Count + " vertices, more than this tool reads.", "Prune the splat.");
                var reader = new PlyValueReader(stream, header.Format, reason => Fail(reason, "Re-export the file."));
                var needed = header.MinimumDataBytes(reader.SizeOf);
                if (needed > stream.Length - stream.Position)
                    throw Fail("is truncated: its header declares " + needed.ToString("0", CultureInfo.InvariantCulture) + " bytes of data, but only " + (stream.Length - stream.Position) + " follow.", "Re-export the file.");
                var centres = new List<Vector3d>();
                var values = new double[vertex.Properties.Count];
                var total = 0;
                foreach (var element in header.Elements)
                {
                    var isVertex = element == vertex;
                    for (long n = 0; n < element.Count; n++)
                    {
                        if (header.Format == "ascii") reader.NextLine();
                        for (var p = 0; p < element.Properties.Count; p++)
                        {
                            var property = element.Properties[p];
                            if (property.IsList)
                            {
                                var count = (int)reader.Read(property.CountType);
                                for (var k = 0; k < count; k++) reader.Read(property.Type);
                            }
                            else
                            {
                                var v = reader.Read(property.Type);
                                if (isVertex) values[p] = v;
                            }
                        }
                        if (!isVertex) continue;
                        total++;
                        if (minOpacity > 0 && !(Sigmoid(values[io]) > minOpacity)) continue;
                        var centre = new Vector3d(values[ix], values[iy], values[iz]);
                        if (centre.IsFinite) centres.Add(centre);
                    }
                    if (isVertex) break; // the centres are all read; later elements do not matter
                }
                return new GaussianPly(centres, total);
            }
        }

        public static double Sigmoid(double logit) => 1 / (1 + Math.Exp(-logit));
    }
}
