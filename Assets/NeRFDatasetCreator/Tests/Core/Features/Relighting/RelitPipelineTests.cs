using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The relit images go through the view's own colour stages (<see cref="ViewFileWriter"/>): a condition whose colour is
    /// the view's own renders gives the view's image byte for byte — matting, straight alpha, the HDR EXR — and, with
    /// exposure, the clean image (a relit image is not exposed). And the analytic lighting on hand-derived numbers.
    /// </summary>
    [TestFixture]
    public class RelitPipelineTests
    {
        TempFolder _temp;

        [SetUp] public void Create() => _temp = new TempFolder();
        [TearDown] public void Delete() => _temp.Dispose();

        /// <summary>Writes the first train view with its relit "same" condition holding <paramref name="relitOf"/>(the view's frame); returns the session.</summary>
        DatasetWriteSession WriteFirstView(string name, Action<DatasetSettings> configure, Func<RawFrame, RawFrame> relitOf, bool straightAlpha = false)
        {
            var options = new AnalyticDataset.Options
            {
                Train = 1, Val = 1, Test = 1, PointCloud = 0,
                Configure = s =>
                {
                    s.Relighting = new RelightingSettings { On = true, Conditions = { new LightingCondition { Name = "same", Kind = LightingKind.Point } } };
                    configure?.Invoke(s);
                },
            };
            var run = AnalyticDataset.Prepare(_temp.Path, name, options);
            Assert.That(run.IsValid, Is.True, string.Join("\n", run.Problems));
            var session = run.Begin();
            var view = run.Plan.Views[0];
            var scene = AnalyticScene.Layout(run.Plan.Normalisation, AnalyticDataset.Centre);
            var frame = AnalyticDataset.Render(scene, AnalyticDataset.Rays(view.TransformMatrix, run.Plan.Intrinsics, null), run.Plan.Intrinsics.Width, run.Plan.Intrinsics.Height,
                options, run.Plan.Normalisation.Scale, options.Supersampling);
            if (straightAlpha) frame = StraightAlphaFrame(frame);
            frame.Relit = new Dictionary<string, RawFrame> { ["same"] = relitOf(frame) };
            new ViewFileWriter(run.Plan, session, ExrWriter.Encode).Write(view, frame, frame);
            return session;
        }

        /// <summary>The same render as linear colour (over black, where the surfaces are opaque or empty) with its mask: the straight-alpha path.</summary>
        static RawFrame StraightAlphaFrame(RawFrame matting)
        {
            var linear = new float[matting.ColorOverBlack.Length];
            for (var i = 0; i < linear.Length; i++) linear[i] = HalfFloat.ToFloat(matting.ColorOverBlack[i]);
            return new RawFrame(matting.Width, matting.Height, matting.Supersampling)
            {
                ColorLinear = linear, Mask = matting.Mask, MaskBytesPerPixel = 1, Depth = matting.Depth, Normals = matting.Normals, NormalsInUnityWorld = false,
            };
        }

        static byte[] Bytes(DatasetWriteSession session, string relative) => File.ReadAllBytes(session.PathOf(relative));

        [Test]
        public void TheViewsOwnColourRelitGivesTheViewsImageByteForByte()
        {
            var session = WriteFirstView("matting", s => s.Hdr.On = true, f => new RawFrame(f.Width, f.Height, f.Supersampling) { ColorOverBlack = f.ColorOverBlack, ColorOverWhite = f.ColorOverWhite });
            Assert.That(Bytes(session, "train/r_0_light_same.png"), Is.EqualTo(Bytes(session, "train/r_0.png")));
            Assert.That(Bytes(session, "train/r_0_light_same_hdr.exr"), Is.EqualTo(Bytes(session, "train/r_0_hdr.exr")));
        }

        [Test]
        public void StraightAlphaTakesTheViewsMask()
        {
            var session = WriteFirstView("straight", null, f => new RawFrame(f.Width, f.Height, f.Supersampling) { ColorLinear = f.ColorLinear }, straightAlpha: true);
            Assert.That(Bytes(session, "train/r_0_light_same.png"), Is.EqualTo(Bytes(session, "train/r_0.png")));
        }

        [Test]
        public void WithExposureARelitImageIsTheCleanImage()
        {
            var session = WriteFirstView("exposed", s =>
            {
                s.Exposure.Mode = ExposureMode.Random;
                s.Exposure.EvMin = 1;
                s.Exposure.EvMax = 1.5;
                s.Exposure.WriteClean = true;
            }, f => new RawFrame(f.Width, f.Height, f.Supersampling) { ColorOverBlack = f.ColorOverBlack, ColorOverWhite = f.ColorOverWhite });
            Assert.That(Bytes(session, "train/r_0_light_same.png"), Is.EqualTo(Bytes(session, "train/r_0_clean.png")));
            Assert.That(Bytes(session, "train/r_0_light_same.png"), Is.Not.EqualTo(Bytes(session, "train/r_0.png")));
        }

        [Test]
        public void AMissingOrMisSizedConditionIsRefusedByName()
        {
            var missing = Assert.Throws<InvalidOperationException>(() => WriteFirstView("missing", null, f => null));
            Assert.That(missing.Message, Does.Contain("no colour for \"same\""));
            var small = Assert.Throws<InvalidParameterException>(() => WriteFirstView("small", null, f => new RawFrame(2, 2, 1) { ColorLinear = new float[16] }));
            Assert.That(small.Problems.Single().Field, Is.EqualTo("frame.Relit[\"same\"]"));
        }

        [Test]
        public void AConstantEnvironmentGivesLambertsAlbedo()
        {
            // E(n) = ∫ L max(0, n·ω) dω = π·L for every normal; outgoing = albedo/π · E = albedo·L.
            var white = new EnvironmentMap(64, 32, Enumerable.Repeat(1f, 64 * 32 * 3).ToArray());
            var irradiance = AnalyticLighting.Irradiance(white, 16);
            foreach (var e in irradiance.Rgb) Assert.That(e, Is.EqualTo(Math.PI).Within(0.01 * Math.PI));
            var shading = AnalyticLighting.Environment(irradiance, 90, 2);
            var result = new double[3];
            shading(Vector3d.Zero, new Vector3d(0.6, 0, 0.8), new[] { 0.5, 0.25, 1 }, result);
            Assert.That(result, Is.EqualTo(new[] { 1.0, 0.5, 2 }).Within(0.02));
        }

        [Test]
        public void AnEnvironmentsIrradianceTurnsWithItsRotation()
        {
            // All the light from +X's half (x > 0): a normal facing +X is lit, one facing −X is not; turned by 180° the other way round.
            var map = new EnvironmentMap(64, 32, new float[64 * 32 * 3]);
            for (var row = 0; row < 32; row++)
                for (var column = 0; column < 64; column++)
                    if (Equirect.PixelDirection(column, row, 64, 32).X > 0)
                        for (var c = 0; c < 3; c++) map.Rgb[(row * 64 + column) * 3 + c] = 1;
            var irradiance = AnalyticLighting.Irradiance(map, 16);
            var result = new double[3];
            var albedo = new[] { 1.0, 1, 1 };
            AnalyticLighting.Environment(irradiance, 0, 1)(Vector3d.Zero, Vector3d.UnitX, albedo, result);
            Assert.That(result[0], Is.EqualTo(1).Within(0.03), "a full hemisphere of 1: albedo");
            AnalyticLighting.Environment(irradiance, 0, 1)(Vector3d.Zero, -Vector3d.UnitX, albedo, result);
            Assert.That(result[0], Is.LessThan(0.03));
            AnalyticLighting.Environment(irradiance, 180, 1)(Vector3d.Zero, -Vector3d.UnitX, albedo, result);
            Assert.That(result[0], Is.EqualTo(1).Within(0.03));
        }

        [Test]
        public void APointLightFallsOffWithDistanceAndCastsShadows()
        {
            // One sphere of radius 1 at the origin; light at (0, 0, 5), intensity 16. The top point (0, 0, 1): r = 4, cos = 1,
            // E = 16/16 = 1, outgoing = albedo/π. A point on the floor below the sphere is shadowed.
            var scene = AnalyticScene.OneSphere(Vector3d.Zero, 1);
            var settings = new DatasetSettings
            {
                Relighting = new RelightingSettings { On = true, Conditions = { new LightingCondition { Name = "p", Kind = LightingKind.Point, Position = new double[] { 0, 0, 5 }, Intensity = 16 } } },
            };
            var shading = AnalyticLighting.For(settings, scene, new Dictionary<string, EnvironmentMap>())["p"];
            var result = new double[3];
            shading(new Vector3d(0, 0, 1), Vector3d.UnitZ, new[] { Math.PI, 0, 0 }, result);
            Assert.That(result[0], Is.EqualTo(1).Within(1e-9));
            shading(new Vector3d(0, 0, -2), Vector3d.UnitZ, new[] { Math.PI, 0, 0 }, result);
            Assert.That(result[0], Is.EqualTo(0), "behind the sphere");
            settings.Relighting.Conditions[0].Shadows = false;
            AnalyticLighting.For(settings, scene, new Dictionary<string, EnvironmentMap>())["p"](new Vector3d(0, 0, -2), Vector3d.UnitZ, new[] { Math.PI, 0, 0 }, result);
            Assert.That(result[0], Is.EqualTo(16 / 49.0).Within(1e-9), "without shadows: E = 16 / 7²");
        }
    }
}
