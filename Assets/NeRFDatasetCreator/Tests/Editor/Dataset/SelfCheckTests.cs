using System;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;
using UnityEditor;
using UnityEngine;
using UnityEngine.SceneManagement;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>
    /// Issue 21 in Unity: every capture is checked by Core's <see cref="DatasetCheck"/> and carries its
    /// <see cref="DatasetCheck.ReportFileName"/>; a large capture is preceded by a calibration capture whose check stops
    /// a broken pipeline. The broken pass planted here is real: a shader that moves its vertices, which the colour pass
    /// follows and the data passes (undisplaced geometry) do not, so alpha and mask disagree.
    /// </summary>
    [TestFixture]
    [Category("GPU")]
    public class SelfCheckTests
    {
        Scene _scene;
        GameObject _sphere;
        string _project;

        // An unlit shader whose vertices are pushed 0.4 object units along x: colour shows the object moved, the
        // mask/depth/normal passes draw the mesh where it is.
        const string DisplacingShader = @"Shader ""Hidden/NerfTests/Displaced""
{
    SubShader
    {
        Pass
        {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include ""UnityCG.cginc""
            float4 vert(float4 v : POSITION) : SV_POSITION { v.x += 0.4; return UnityObjectToClipPos(v); }
            fixed4 frag() : SV_Target { return fixed4(0.8, 0.5, 0.2, 1); }
            ENDCG
        }
    }
}";

        [SetUp]
        public void SetUp()
        {
            TestScene.RequireRendering();
            _scene = TestScene.Open();
            _sphere = TestScene.LitSphere("Self-check test sphere");
            _project = Path.Combine(Path.GetTempPath(), "nerf-self-check-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_project);
        }

        [TearDown]
        public void TearDown()
        {
            TestScene.Close(_scene);
            if (_project != null && Directory.Exists(_project)) Directory.Delete(_project, true);
        }

        static DatasetSettings Settings(int train)
        {
            var settings = new DatasetSettings { Name = "sphere", Width = 48, Height = 48, Supersampling = 2, Distance = 3, PointCloudPoints = 2000 };
            settings.Train.Count = train;
            settings.Val.Count = 2;
            settings.Test.Count = 6;
            settings.Test.Depth = ExtraOutput.Png;
            settings.Test.Normal = ExtraOutput.Png;
            settings.Test.Mask = true;
            return settings;
        }

        static string[] PreflightFolders() =>
            Directory.GetDirectories(Path.GetTempPath(), PreflightCheck.FolderPrefix + "*").OrderBy(f => f, StringComparer.Ordinal).ToArray();

        [Test]
        public void TheSelfCheckPassesOnAGpuCaptureAndItsReportIsInTheDataset()
        {
            var prepared = DatasetCapture.Prepare(Settings(8), _sphere, _project);
            Assert.That(prepared.Problems.Select(p => p.ToString()), Is.Empty);
            var result = DatasetCapture.RunBlocking(prepared, new SilentProgress());
            Assert.That(result.Succeeded, Is.True, result.Message);
            Assert.That(result.Check, Is.Not.Null, "every finished capture is checked");
            Assert.That(result.CheckFailed, Is.False, result.Message);
            Assert.That(result.Check.ViewsChecked, Is.EqualTo(16));
            Assert.That(result.Message, Does.Contain("Self-check of 16 views passed"));
            var report = JObject.Parse(File.ReadAllText(Path.Combine(result.DatasetFolder, DatasetCheck.ReportFileName)));
            Assert.That(report["failed"].Value<bool>(), Is.False);
            Assert.That(report["checks"].Select(c => (string)c["name"]), Does.Contain("multi-view geometry").And.Contain("alpha vs mask"));
            Assert.That(OwnDataset.WhyNotOurs(result.DatasetFolder), Is.Null, "the report is one of the dataset's own files");
            var config = JObject.Parse(File.ReadAllText(Path.Combine(result.DatasetFolder, "dataset_config.json")));
            // A clean scene: the two colour renders differ by the clear colour only (nothing animates, no full-screen
            // feature), and background samples are the clear pair; the mask pass's edges may differ from the colour pass's
            // by a sample where the engine rounds the two projections differently, never by 0.1 % of a view.
            Assert.That(config.SelectToken("statistics.mattingDarkerOverWhiteSamples")?.Value<double>(), Is.EqualTo(0), result.Message);
            Assert.That(config.SelectToken("statistics.mattingStrayBackgroundSamples"), Is.Not.Null, "the mask pass ran for the diagnostics");
            Assert.That(config.SelectToken("statistics.mattingViewsAboveThreshold")?.Value<double>(), Is.EqualTo(0), result.Message);
        }

        [Test]
        public void ThePreflightCatchesAPlantedBrokenPassAndLeavesNothingBehind()
        {
            var shader = ShaderUtil.CreateShaderAsset(DisplacingShader);
            var material = new Material(shader);
            try
            {
                Assert.That(shader.isSupported, Is.True, "the planted shader compiles here");
                _sphere.GetComponent<Renderer>().sharedMaterial = material;
                var before = PreflightFolders();

                var prepared = DatasetCapture.Prepare(Settings(60), _sphere, _project);
                Assert.That(prepared.Problems.Select(p => p.ToString()), Is.Empty);
                Assert.That(prepared.ViewCount, Is.GreaterThan(PreflightCheck.MinViews));
                var result = DatasetCapture.RunBlocking(prepared, new SilentProgress());

                Assert.That(result.Succeeded, Is.False, "the preflight stops the capture: " + result.Message);
                Assert.That(result.Message, Does.Contain("preflight stopped the capture").And.Contain("[alpha vs mask]"),
                    "a problem line of the alpha-vs-mask check names the fault");
                Assert.That(Directory.Exists(prepared.DatasetFolder), Is.False, "nothing was captured");
                Assert.That(Directory.GetDirectories(_project, "*", SearchOption.AllDirectories), Is.Empty, "no partial folder either");
                Assert.That(PreflightFolders(), Is.EqualTo(before), "the calibration's temporary folder is deleted");

                // Without the preflight the capture runs, and its own self-check finds the same fault.
                var settings = Settings(60);
                settings.Preflight = false;
                var unchecked_ = DatasetCapture.RunBlocking(DatasetCapture.Prepare(settings, _sphere, _project), new SilentProgress());
                Assert.That(unchecked_.Succeeded, Is.True, unchecked_.Message);
                Assert.That(unchecked_.CheckFailed, Is.True, "the post-capture check catches it: " + unchecked_.Message);
                Assert.That(File.Exists(Path.Combine(unchecked_.DatasetFolder, DatasetCheck.ReportFileName)), Is.True);
            }
            finally
            {
                UnityEngine.Object.DestroyImmediate(material);
                UnityEngine.Object.DestroyImmediate(shader);
            }
        }

        sealed class SilentProgress : NerfDatasetCreator.Editor.ICaptureProgress
        {
            public void Report(ThroughputMeter meter) { }
            public bool CancelRequested => false;
            public void Close() { }
        }
    }
}
