using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// <see cref="DatasetConfig"/>, the one reader and writer of dataset_config.json: what <see cref="DatasetConfig.Write"/>
    /// writes reads back section by section; a missing, unreadable or malformed file gives the outcome and the messages its
    /// callers gave when each parsed the file itself.
    /// </summary>
    [TestFixture]
    // Sets FileOps.Faults, which every file operation of the process sees: never beside another fixture (dotnet runs
    // fixtures side by side, Tests/Core.Tests/ParallelFixtures.cs).
    [Parallelizable(ParallelScope.None)]
    public class DatasetConfigTests
    {
        static readonly DateTime Created = new DateTime(2026, 11, 22, 12, 30, 5, DateTimeKind.Utc);

        [TearDown]
        public void TearDown()
        {
            FileOps.Faults = null;
        }

        static CapturePlan MultiViewPlan()
        {
            var s = new DatasetSettings { Seed = 7, Width = 16, Height = 16 };
            s.Train.Count = 6;
            s.Val.Count = 2;
            s.Test.Count = 2;
            s.Time.Mode = TimeMode.MultiView;
            s.Time.StartSeconds = 2;
            s.Time.EndSeconds = 6;
            s.Time.Steps = 3;
            s.Background = BackgroundSettings.Parse("#336699");
            return CapturePlan.Build(s, new PlanTarget(new Vector3d(1, 2, 3), 0.75));
        }

        static DatasetConfigFile WriteAndRead(TempFolder folder, string text)
        {
            File.WriteAllText(folder.Combine(DatasetLayout.ConfigFileName), text);
            return DatasetConfig.Read(folder.Path);
        }

        [Test]
        public void WhatIsWrittenReadsBackSectionBySection()
        {
            var plan = MultiViewPlan();
            var cloud = new PointCloudRecord("points3d.ply", "0123abcd", 1234);
            var geometry = new JObject { ["file"] = "geometry/target_mesh.ply", ["sha256"] = "beef", ["triangles"] = 12 };
            using (var folder = new TempFolder())
            {
                var read = WriteAndRead(folder, DatasetConfig.Write(plan, new Provenance(Created, "2022.3.45f1", "unity-batch"), cloud, geometry));
                Assert.That(read.State, Is.EqualTo(DatasetConfigState.Read));
                Assert.That(read.Error, Is.Null);
                var config = read.Config;
                Assert.That(config.Generator, Is.EqualTo("NeRF Dataset Creator"));
                Assert.That(config.IsThisPlugin, Is.True);
                Assert.That(config.ImagesRendered, Is.True);
                Assert.That(read.IsPlanOnly, Is.False);
                Assert.That(config.BackgroundText, Is.EqualTo("#336699"));
                Assert.That(config.Background.R, Is.EqualTo(0x33 / 255.0));
                Assert.That(config.Background.B, Is.EqualTo(0x99 / 255.0));
                Assert.That(config.OpaqueBackground, Is.True);
                Assert.That(config.InsideOut, Is.False, "scene cameras, not a volume");

                Assert.That(config.Time.Mode, Is.EqualTo("multi-view"));
                Assert.That(config.Time.StartSeconds, Is.EqualTo(2.0));
                Assert.That(config.Time.EndSeconds, Is.EqualTo(6.0));
                Assert.That(config.Time.Steps, Is.EqualTo(3));

                Assert.That(config.PointCloud.File, Is.EqualTo("points3d.ply"));
                Assert.That(config.PointCloud.Sha256, Is.EqualTo("0123abcd"));
                Assert.That(config.PointCloud.Points, Is.EqualTo(1234));
                Assert.That(config.GeometryEntries.Select(e => e.File), Is.EqualTo(new[] { "geometry/target_mesh.ply" }));
                Assert.That(config.GeometryEntries[0].Sha256, Is.EqualTo("beef"));
                Assert.That(config.GeometryIsPerStep, Is.False);

                // |s·(P·c − centre)| + s·b, as the plan computed it when it was captured.
                Assert.That(config.TargetReach(), Is.EqualTo(plan.TargetReach).Within(1e-12));
                // Strings stay as written: a DateTime would come back in another format.
                Assert.That(config.Json["createdUtc"].Type, Is.EqualTo(JTokenType.String));
                Assert.That((string)config.Json["createdUtc"], Is.EqualTo("2026-11-22T12:30:05Z"));

                // The settings object is a settings file: the settings reader gives the plan's settings back.
                var settings = DatasetSettingsJson.Read(config.Settings.ToString());
                Assert.That(DatasetSettingsJson.Write(settings.Settings), Is.EqualTo(DatasetSettingsJson.Write(plan.Settings)));
            }
        }

        [Test]
        public void AStillTransparentPlanReadsAsOne()
        {
            var s = new DatasetSettings { Seed = 1 };
            s.Train.Count = 2;
            var plan = CapturePlan.Build(s, PlanTarget.AtOrigin);
            using (var folder = new TempFolder())
            {
                var read = WriteAndRead(folder, DatasetConfig.Write(plan, new Provenance(Created, imagesRendered: false)));
                Assert.That(read.IsPlanOnly, Is.True);
                Assert.That(read.Config.ImagesRendered, Is.False);
                Assert.That(read.Config.Time, Is.Null);
                Assert.That(read.Config.PointCloud, Is.Null);
                Assert.That(read.Config.GeometryEntries, Is.Empty);
                Assert.That(read.Config.BackgroundText, Is.EqualTo("transparent"));
                Assert.That(read.Config.OpaqueBackground, Is.False);
            }
        }

        static string JObjectParseMessage(string text)
        {
            try
            {
                JObject.Parse(text);
            }
            catch (JsonException e)
            {
                return e.Message;
            }
            throw new AssertionException("JObject.Parse accepted " + text);
        }

        [Test]
        public void AnEmptyConfigIsRefusedUnreadAsAPipeOrDeviceWouldBe()
        {
            // 0 bytes: an empty file, a FIFO and /dev/zero look alike to .NET, and none is opened (ReadableFile).
            using (var folder = new TempFolder())
            {
                var read = WriteAndRead(folder, "");
                Assert.That(read.State, Is.EqualTo(DatasetConfigState.Unreadable));
                Assert.That(read.Error, Is.EqualTo(folder.Combine("dataset_config.json") + " " + ReadableFile.EmptyReason));
            }
        }

        [TestCase("{\"generator\": ")]
        [TestCase("{\"generator\": \"NeRF Dataset Creator\"} trailing")]
        public void TextThatIsNotJsonIsNamedWithTheParsersWords(string text)
        {
            using (var folder = new TempFolder())
            {
                var read = WriteAndRead(folder, text);
                Assert.That(read.State, Is.EqualTo(DatasetConfigState.NotJson));
                Assert.That(read.Config, Is.Null);
                Assert.That(read.Error, Is.EqualTo(JObjectParseMessage(text)), "the message JObject.Parse gave each caller before");
                Assert.That(read.IsPlanOnly, Is.False);

                var warnings = new List<ValidationProblem>();
                Assert.That(DatasetTargetReach.Read(folder.Path, warnings), Is.Null);
                Assert.That(warnings.Select(w => w.Field + " " + w.Reason), Is.EqualTo(new[]
                {
                    "dataset_config.json is not valid JSON (" + JObjectParseMessage(text) + "), so the target's size is unknown.",
                }));
                Assert.That(OwnDataset.WhyNotOurs(folder.Path), Is.EqualTo("its dataset_config.json cannot be read (" + JObjectParseMessage(text) + ")"));
            }
        }

        [Test]
        public void JsonThatIsNotAnObjectIsToldApart()
        {
            using (var folder = new TempFolder())
            {
                var read = WriteAndRead(folder, "[1, 2]");
                Assert.That(read.State, Is.EqualTo(DatasetConfigState.NotAnObject));
                Assert.That(read.Error, Is.EqualTo(JObjectParseMessage("[1, 2]")));
                // Proof of ownership is missing, not unreadable: the words OwnDataset always gave an array.
                Assert.That(OwnDataset.WhyNotOurs(folder.Path), Is.EqualTo("its dataset_config.json does not name \"NeRF Dataset Creator\" as its generator"));
            }
        }

        [Test]
        public void AnUnreadableFileIsNamedAndValidateReportsIt()
        {
            using (var folder = new TempFolder())
            {
                var path = folder.Combine(DatasetLayout.ConfigFileName);
                File.WriteAllText(path, "{}");
                FileOps.Faults = FileFaultPlan.FailingAt(1, (op, p) => new UnauthorizedAccessException("Access to the path is denied."), p => p == path);
                var read = DatasetConfig.Read(folder.Path);
                Assert.That(read.State, Is.EqualTo(DatasetConfigState.Unreadable));
                Assert.That(read.Error, Is.EqualTo(path + ": Access to the path is denied."), "FileOps names the file");
                Assert.That(() => read.ThrowIfUnreadable(), Throws.TypeOf<UnauthorizedAccessException>());

                FileOps.Faults = FileFaultPlan.FailingAt(1, (op, p) => new IOException("Input/output error"), p => p == path);
                var report = DatasetValidator.Validate(folder.Path);
                Assert.That(report.Problems.Select(p => p.ToString()),
                    Does.Contain("dataset_config.json: cannot be read: " + path + ": Input/output error (check the file's permissions)."));
            }
        }

        [Test]
        public void ANerfSyntheticFolderHasNoConfigAndEveryReaderSaysWhatItSaidBefore()
        {
            using (var folder = new TempFolder())
            {
                File.WriteAllText(folder.Combine("transforms_train.json"), "{\"camera_angle_x\": 0.69, \"frames\": []}");
                var read = DatasetConfig.Read(folder.Path);
                Assert.That(read.State, Is.EqualTo(DatasetConfigState.Missing));
                Assert.That(read.Exists, Is.False);
                Assert.That(read.Config, Is.Null);
                Assert.That(read.Error, Is.Null);
                Assert.That(read.IsPlanOnly, Is.False);
                Assert.That(() => read.ThrowIfUnreadable(), Throws.Nothing);

                var warnings = new List<ValidationProblem>();
                Assert.That(DatasetTargetReach.Read(read, warnings), Is.Null);
                Assert.That(PointCloudOwnership.IsOwn(folder.Path, read, warnings), Is.False);
                Assert.That(warnings, Is.Empty, "nerf_synthetic has neither a config nor a cloud: nothing to warn about");
                Assert.That(OwnDataset.WhyNotOurs(folder.Path), Is.EqualTo("it has no dataset_config.json, so nothing proves this plugin wrote it"));
                Assert.That(DatasetValidator.Validate(folder.Path).Problems.Select(p => p.File), Does.Not.Contain("dataset_config.json"));
            }
        }

        [Test]
        public void SectionsOfTheWrongTypeReadAsNotRecorded()
        {
            var config = DatasetConfig.Parse("{\"generator\": 3, \"imagesRendered\": \"false\", \"settings\": [], \"time\": {\"mode\": 2, \"steps\": 99999999999, \"startSeconds\": \"0\"}}");
            Assert.That(config.Generator, Is.Null);
            Assert.That(config.IsThisPlugin, Is.False);
            Assert.That(config.ImagesRendered, Is.Null, "only a boolean counts, as validate and OwnDataset read it");
            Assert.That(config.Settings, Is.Null);
            Assert.That(config.BackgroundText, Is.Null);
            Assert.That(config.InsideOut, Is.False);
            Assert.That(config.Time.Mode, Is.Null);
            Assert.That(config.Time.Steps, Is.Null, "beyond an int");
            Assert.That(config.Time.StartSeconds, Is.Null);
        }

        [TestCase("transparent", false)]
        [TestCase("sky", true)]
        [TestCase("#000000", true)]
        [TestCase("TRANSPARENT", false)]
        [TestCase("#12", false)]
        public void TheBackgroundIsReadAsTheSettingsReaderReadsIt(string background, bool opaque)
        {
            var config = DatasetConfig.Parse(new JObject { ["settings"] = new JObject { ["background"] = background } }.ToString());
            Assert.That(config.OpaqueBackground, Is.EqualTo(opaque));
            Assert.That(config.BackgroundText, Is.EqualTo(background));
        }
    }
}
