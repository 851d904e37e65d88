using System;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>dataset_config.json's <c>materials</c> record: only with materials on, the capture's facts sorted, nothing invented without them.</summary>
    [TestFixture]
    public class MaterialRecordTests
    {
        static JObject Config(Action<DatasetSettings> configure, MaterialCaptureFacts facts)
        {
            var s = new DatasetSettings { Name = "lego" };
            s.Train.Count = 2;
            s.Val.Count = 1;
            s.Test.Count = 1;
            configure(s);
            var plan = CapturePlan.Build(s, new PlanTarget(new Vector3d(0, 0, 0), 1));
            return JObject.Parse(DatasetConfig.Write(plan, new Provenance(new DateTime(2026, 12, 7, 0, 0, 0, DateTimeKind.Utc)) { Materials = facts }));
        }

        [Test]
        public void OffWritesNoRecord()
        {
            Assert.That(Config(s => { }, new MaterialCaptureFacts("urp", new[] { "Universal Render Pipeline/Lit" }, null))["materials"], Is.Null);
        }

        [Test]
        public void TheCapturesShadersAreSortedAndTheEncodingsAreThoseOfThePassesOn()
        {
            var record = Config(s => { s.Materials.On = true; s.Materials.Metallic = false; },
                new MaterialCaptureFacts("builtin", new[] { "Standard (Specular setup)", "Standard", "Standard" }, new[] { "Custom/Toon", "", "Custom/Hair" }))["materials"];
            Assert.That(record["passes"].Select(t => (string)t), Is.EqualTo(new[] { "albedo", "roughness" }));
            Assert.That(((JObject)record["encodings"]).Properties().Select(p => p.Name + "=" + (string)p.Value), Is.EqualTo(new[] { "albedo_png=srgb", "roughness_png=linear" }));
            Assert.That((string)record["pipeline"], Is.EqualTo("builtin"));
            Assert.That(record["supported_shaders"].Select(t => (string)t), Is.EqualTo(new[] { "Standard", "Standard (Specular setup)" }));
            Assert.That(record["unsupported_shaders"].Select(t => (string)t), Is.EqualTo(new[] { "Custom/Hair", "Custom/Toon" }));
            Assert.That(MaterialRecord.PngEncoding((JObject)JObject.Parse("{\"materials\":" + record + "}"), "roughness"), Is.EqualTo("linear"));
        }

        [Test]
        public void WithoutTheCapturesFactsThePipelineIsNullAndTheListsEmpty()
        {
            var record = Config(s => s.Materials.On = true, null)["materials"];
            Assert.That(record["pipeline"].Type, Is.EqualTo(JTokenType.Null));
            Assert.That(record["supported_shaders"], Is.Empty);
            Assert.That(record["unsupported_shaders"], Is.Empty);
        }
    }
}
