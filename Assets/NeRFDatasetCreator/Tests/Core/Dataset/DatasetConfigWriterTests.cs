using System;
using System.IO;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class DatasetConfigWriterTests
    {
        static CapturePlan Plan()
        {
            var s = new DatasetSettings { Seed = 99, Name = "lego" };
            s.Train.Count = 3;
            s.Val.Count = 2;
            s.Test.Count = 1;
            return CapturePlan.Build(s, new PlanTarget(new Vector3d(1, 2, 3), 0.75));
        }

        [Test]
        public void HoldsProvenanceAndTheSettingsAsAConfig()
        {
            var plan = Plan();
            var provenance = new Provenance(new DateTime(2026, 11, 22, 12, 30, 5, DateTimeKind.Utc), "2022.3.45f1", "unity-batch");
            provenance.Statistics["viewsPerSecond"] = 12.5;
            var config = JObject.Parse(DatasetConfig.Write(plan, provenance));
            Assert.That((string)config["generator"], Is.EqualTo("NeRF Dataset Creator"));
            Assert.That((string)config["pluginVersion"], Is.EqualTo(PluginInfo.Version));
            Assert.That((string)config["unityVersion"], Is.EqualTo("2022.3.45f1"));
            Assert.That((string)config["tool"], Is.EqualTo("unity-batch"));
            Assert.That((bool)config["imagesRendered"], Is.True);
            Assert.That(config["createdUtc"].ToString(Formatting.None), Is.EqualTo("\"2026-11-22T12:30:05Z\""));
            Assert.That((long)config["seed"], Is.EqualTo(99));
            Assert.That((double)config["distance"], Is.EqualTo(4.0));
            Assert.That(config["target"]["unityCentre"].ToObject<double[]>(), Is.EqualTo(new[] { 1.0, 2.0, 3.0 }));
            Assert.That((double)config["target"]["boundingRadius"], Is.EqualTo(0.75));
            Assert.That((int)config["views"]["train"], Is.EqualTo(3));
            Assert.That((double)config["statistics"]["viewsPerSecond"], Is.EqualTo(12.5));

            // The "settings" object is a complete config: reading it gives the same settings back.
            var settings = DatasetSettingsJson.Read(config["settings"].ToString());
            Assert.That(settings.Warnings, Is.Empty);
            Assert.That(DatasetSettingsJson.Write(settings.Settings), Is.EqualTo(DatasetSettingsJson.Write(plan.Settings)));
        }

        [Test]
        public void UnknownUnityVersionIsNull()
        {
            var config = JObject.Parse(DatasetConfig.Write(Plan(), new Provenance(DateTime.UtcNow)));
            Assert.That(config["unityVersion"].Type, Is.EqualTo(JTokenType.Null));
            Assert.That(config["statistics"], Is.Null);
        }

        [Test]
        public void LocalTimesAreWrittenInUtc()
        {
            var local = new DateTime(2026, 6, 1, 12, 0, 0, DateTimeKind.Local);
            var config = JObject.Parse(DatasetConfig.Write(Plan(), new Provenance(local)));
            var expected = local.ToUniversalTime().ToString("yyyy-MM-dd'T'HH:mm:ss'Z'", System.Globalization.CultureInfo.InvariantCulture);
            Assert.That(config["createdUtc"].ToString(Formatting.None), Is.EqualTo("\"" + expected + "\""));
        }
    }
}
