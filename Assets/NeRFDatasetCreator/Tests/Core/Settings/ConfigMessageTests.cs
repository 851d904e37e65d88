using System.IO;
using System.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Issue 23's first-hour mistakes in a config file: each gives one clear error naming the file, the line and the fix
    /// (not Newtonsoft's or the runtime's text), every wrong value is reported at once, and a misspelled key is matched.
    /// </summary>
    [TestFixture]
    public class ConfigMessageTests
    {
        [Test]
        public void AnEmptyFileSaysItIsEmptyAndWhatToWrite()
        {
            foreach (var text in new[] { "", "  \n" })
            {
                var e = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read(text, "lego.json"));
                Assert.That(e.Message, Does.StartWith("lego.json: the file is empty."));
                Assert.That(e.Message, Does.Contain("write {} for the defaults"));
                Assert.That(e.Message, Does.Not.Contain("JsonReader"));
            }
        }

        [Test]
        public void AFolderGivenAsTheConfigIsNamedAsAFolder()
        {
            using (var temp = new TempFolder())
            {
                var folder = temp.Combine("configs");
                Directory.CreateDirectory(folder);
                File.WriteAllText(Path.Combine(folder, "lego.json"), "{}");
                var e = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.ReadFile(folder));
                Assert.That(e.Message, Does.StartWith(folder + ": is a folder, not a config file."));
                Assert.That(e.Message, Does.Contain(Path.Combine(folder, "lego.json")), "points at the config inside it");
                Assert.That(e.Message, Does.Not.Contain("denied"));
            }
        }

        [Test]
        public void AMissingFileIsNamedWithItsFullPath()
        {
            using (var temp = new TempFolder())
            {
                var path = temp.Combine("nope.json");
                var e = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.ReadFile(path));
                Assert.That(e.Message, Does.StartWith(path + ": does not exist"));
            }
        }

        [Test]
        public void AMissingCommaIsReportedAtTheEndOfTheLineThatNeedsIt()
        {
            // Newtonsoft stops at line 3 ("height"); the comma belongs after 400 on line 2, which ends at column 14.
            var text = "{\n  \"width\": 400\n  \"height\": 400\n}\n";
            var e = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read(text, "lego.json"));
            Assert.That(e.Line, Is.EqualTo(2));
            Assert.That(e.Column, Is.EqualTo(14));
            Assert.That(e.Message, Is.EqualTo("lego.json(2,14): a comma is missing after this value (entries of an object or a list are separated by commas). Add a comma at the end of line 2."));
        }

        [Test]
        public void AMissingCommaAfterAnObjectOnItsOwnLine()
        {
            var text = "{\n  \"camera\": { \"nearClip\": 0.5 }\n\n  \"width\": 400\n}";
            var e = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read(text, "c.json"));
            Assert.That((e.Line, e.Column), Is.EqualTo((2, 31)), "the closing brace of camera");
        }

        [Test]
        public void AnUnclosedObjectAndTrailingTextSayWhatToAdd()
        {
            var open = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{ \"width\": 400", "c.json"));
            Assert.That(open.Detail, Does.Contain("Add the missing } or ]"));
            var unquoted = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{ \"background\": white }", "c.json"));
            Assert.That(unquoted.Detail, Does.Contain("Put text in double quotes"));
        }

        [Test]
        public void EveryTypeErrorIsReportedNotOnlyTheFirst()
        {
            var text = "{\n  \"width\": \"400\",\n  \"height\": true,\n  \"camera\": { \"nearClip\": \"near\" },\n  \"splits\": { \"test\": { \"mask\": 1 } }\n}";
            var e = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read(text, "lego.json"));
            Assert.That(e.All.Select(x => x.Field), Is.EqualTo(new[] { "width", "height", "camera.nearClip", "splits.test.mask" }));
            Assert.That(e.All.Select(x => x.Line), Is.EqualTo(new[] { 2, 3, 4, 5 }));
            // The first stays the exception's own place, as callers that show one error read it.
            Assert.That((e.Field, e.Line), Is.EqualTo(("width", 2)));
            Assert.That(e.Message.Split('\n'), Has.Length.EqualTo(4));
            Assert.That(e.Message.Split('\n')[2], Is.EqualTo("lego.json(4,32): camera.nearClip: must be a number, not \"near\"."));
        }

        [Test]
        public void OneTypeErrorIsItsOwnList()
        {
            var e = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{ \"width\": \"400\" }", "c.json"));
            Assert.That(e.All, Is.EqualTo(new[] { e }));
        }

        [Test]
        public void AMisspelledSplitSaysDidYouMeanTrain()
        {
            var read = DatasetSettingsJson.Read("{ \"splits\": { \"tran\": { \"count\": 5 } } }");
            var warning = read.Warnings.Single();
            Assert.That(warning.Field, Is.EqualTo("splits.tran"));
            Assert.That(warning.Fix, Does.EndWith("Did you mean \"train\"?"));
        }

        [Test]
        public void MisspelledKeysAndValuesAreMatchedWhenClose()
        {
            Assert.That(DatasetSettingsJson.Read("{ \"widht\": 3 }").Warnings.Single().Fix, Does.EndWith("Did you mean \"width\"?"));
            Assert.That(DatasetSettingsJson.Read("{ \"camera\": { \"nearclip\": 3 } }").Warnings.Single().Fix, Does.EndWith("Did you mean \"nearClip\"?"));
            var loader = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{ \"loaders\": [\"nerfstudi\"] }"));
            Assert.That(loader.Detail, Does.EndWith("Did you mean \"nerfstudio\"?"));
            var mode = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{ \"normalisation\": \"recenter\" }"));
            Assert.That(mode.Detail, Does.EndWith("Did you mean \"recentre\"?"));
            var kind = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{ \"splits\": { \"val\": { \"formation\": { \"kind\": \"obrit\" } } } }"));
            Assert.That(kind.Detail, Does.EndWith("Did you mean \"orbit\"?"));
            var time = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{ \"time\": { \"mode\": \"multiview\" } }"));
            Assert.That(time.Detail, Does.EndWith("Did you mean \"multi-view\"?"));
            var source = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{ \"time\": { \"sources\": [\"animater\"] } }"));
            Assert.That(source.Detail, Does.EndWith("Did you mean \"animator\"?"));
            var depth = Assert.Throws<SettingsFormatException>(() => DatasetSettingsJson.Read("{ \"splits\": { \"train\": { \"depth\": \"pgn\" } } }"));
            Assert.That(depth.Detail, Does.EndWith("Did you mean \"png\"?"));
            // Nothing close: no guess.
            Assert.That(DatasetSettingsJson.Read("{ \"colour\": 3 }").Warnings.Single().Fix, Does.Not.Contain("Did you mean"));
        }

        [Test]
        public void EditDistanceCountsASwapAsOneEdit()
        {
            Assert.That(SpellingSuggestion.Distance("tran", "train"), Is.EqualTo(1));
            Assert.That(SpellingSuggestion.Distance("widht", "width"), Is.EqualTo(1));
            Assert.That(SpellingSuggestion.Distance("kitten", "sitting"), Is.EqualTo(3));
            Assert.That(SpellingSuggestion.Closest("tset", new[] { "train", "val", "test" }), Is.EqualTo("test"));
            Assert.That(SpellingSuggestion.Closest("x", new[] { "train", "val", "test" }), Is.Null);
            Assert.That(SpellingSuggestion.Closest("val", new[] { "train", "val", "test" }), Is.Null, "an exact name needs no suggestion");
        }

        [Test]
        public void TheHeadlessPlanAsksForANumberNotATargetWithRenderers()
        {
            var settings = new DatasetSettings { AutoDistance = true };
            var headless = CapturePlan.Check(settings, PlanTarget.Headless).Single();
            Assert.That(headless.Field, Is.EqualTo("distance"));
            Assert.That(headless.Fix, Does.Not.Contain("renderers"));
            Assert.That(headless.Fix, Does.StartWith("Give the distance as a number"));
            // In Unity a target without renderers is what to fix.
            var unity = CapturePlan.Check(settings, PlanTarget.AtOrigin).Single();
            Assert.That(unity.Fix, Does.Contain("Pick a target with renderers"));
        }
    }
}
