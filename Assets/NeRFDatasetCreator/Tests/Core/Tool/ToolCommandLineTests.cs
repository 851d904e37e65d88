using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class ToolCommandLineTests
    {
        [Test]
        public void Plan()
        {
            var p = ToolCommandLine.Parse(new[] { "plan", "--config", "s.json", "--out", "out/lego" });
            Assert.That(p.Errors, Is.Empty);
            Assert.That(p.Command, Is.EqualTo("plan"));
            Assert.That(p.ConfigPath, Is.EqualTo("s.json"));
            Assert.That(p.OutputFolder, Is.EqualTo("out/lego"));
        }

        [Test]
        public void OptionsWithEquals()
        {
            var p = ToolCommandLine.Parse(new[] { "plan", "--out=d", "--config=c.json" });
            Assert.That(p.Errors, Is.Empty);
            Assert.That(p.ConfigPath, Is.EqualTo("c.json"));
            Assert.That(p.OutputFolder, Is.EqualTo("d"));
        }

        [Test]
        public void Validate()
        {
            var p = ToolCommandLine.Parse(new[] { "validate", "data/lego" });
            Assert.That(p.Errors, Is.Empty);
            Assert.That(p.Command, Is.EqualTo("validate"));
            Assert.That(p.DatasetFolder, Is.EqualTo("data/lego"));
        }

        [Test]
        public void MergeCopiesByDefault()
        {
            var p = ToolCommandLine.Parse(new[] { "merge", "--out", "lego", "shards/shard-0", "shards/shard-1" });
            Assert.That(p.Errors, Is.Empty);
            Assert.That(p.Command, Is.EqualTo("merge"));
            Assert.That(p.OutputFolder, Is.EqualTo("lego"));
            Assert.That(p.ShardFolders, Is.EqualTo(new[] { "shards/shard-0", "shards/shard-1" }));
            Assert.That(p.MoveFiles, Is.False);
        }

        [TestCase("copy", false)]
        [TestCase("move", true)]
        public void MergeFiles(string files, bool move)
        {
            var p = ToolCommandLine.Parse(new[] { "merge", "s0", "--files", files, "s1", "--out=lego" });
            Assert.That(p.Errors, Is.Empty);
            Assert.That(p.MoveFiles, Is.EqualTo(move));
            Assert.That(p.ShardFolders, Is.EqualTo(new[] { "s0", "s1" }), "shard folders may come before, between and after options");
        }

        [TestCase("nerfstudio", ExportTarget.Nerfstudio)]
        [TestCase("colmap", ExportTarget.Colmap)]
        [TestCase("NGP", ExportTarget.Ngp)]
        public void Convert(string to, ExportTarget target)
        {
            var p = ToolCommandLine.Parse(new[] { "convert", "data/lego", "--to", to });
            Assert.That(p.Errors, Is.Empty);
            Assert.That(p.Command, Is.EqualTo("convert"));
            Assert.That(p.DatasetFolder, Is.EqualTo("data/lego"));
            Assert.That(p.Target, Is.EqualTo(target));
            Assert.That(p.OutputFolder, Is.Null, "the format's default place");
        }

        [Test]
        public void ConvertWithOut()
        {
            var p = ToolCommandLine.Parse(new[] { "convert", "--to=colmap", "--out", "exports/lego-colmap", "data/lego" });
            Assert.That(p.Errors, Is.Empty);
            Assert.That(p.OutputFolder, Is.EqualTo("exports/lego-colmap"));
            Assert.That(p.DatasetFolder, Is.EqualTo("data/lego"));
        }

        [Test]
        public void ConvertToColmapWithDepths_IsAFlagWithoutValue()
        {
            var p = ToolCommandLine.Parse(new[] { "convert", "data/lego", "--depths", "--to", "colmap" });
            Assert.That(p.Errors, Is.Empty);
            Assert.That(p.Depths, Is.True);
            Assert.That(p.DatasetFolder, Is.EqualTo("data/lego"), "--depths does not swallow the next argument");
            Assert.That(ToolCommandLine.Parse(new[] { "convert", "data/lego", "--to", "colmap" }).Depths, Is.False);
        }

        [TestCase(new string[0], "no command")]
        [TestCase(new[] { "convert", "d", "--to", "ngp", "--depths" }, "use it with --to colmap")]
        [TestCase(new[] { "convert", "d", "--to", "colmap", "--depths=yes" }, "--depths takes no value")]
        [TestCase(new[] { "validate", "d", "--depths" }, "validate does not know the option --depths")]
        [TestCase(new[] { "render" }, "unknown command 'render'")]
        [TestCase(new[] { "plan", "--config", "s.json" }, "plan needs --out")]
        [TestCase(new[] { "plan", "--out", "d" }, "plan needs --config")]
        [TestCase(new[] { "plan", "--config" }, "--config needs a value")]
        [TestCase(new[] { "plan", "--config", "a", "--config", "b", "--out", "d" }, "given twice")]
        [TestCase(new[] { "plan", "--config", "a", "--out", "d", "--fast", "yes" }, "does not know the option --fast")]
        [TestCase(new[] { "validate" }, "exactly one dataset folder")]
        [TestCase(new[] { "validate", "a", "b" }, "exactly one dataset folder")]
        [TestCase(new[] { "validate", "a", "--to", "ngp" }, "validate does not know the option --to")]
        [TestCase(new[] { "merge", "s0", "s1" }, "merge needs --out")]
        [TestCase(new[] { "merge", "--out", "lego" }, "merge needs the shard folders")]
        [TestCase(new[] { "merge", "--out", "lego", "--files", "link", "s0" }, "--files = link: is not copy or move")]
        [TestCase(new[] { "merge", "--out", "lego", "--to", "ngp", "s0" }, "merge does not know the option --to")]
        [TestCase(new[] { "convert", "d" }, "convert needs --to nerfstudio|colmap|ngp")]
        [TestCase(new[] { "convert", "--to", "ngp" }, "convert needs exactly one dataset folder")]
        [TestCase(new[] { "convert", "a", "b", "--to", "ngp" }, "convert needs exactly one dataset folder")]
        [TestCase(new[] { "convert", "d", "--to", "blender" }, "--to = blender: is not an export format. Use one of: nerfstudio, colmap, ngp, dynamic3dgs, gaussian-grouping.")]
        [TestCase(new[] { "convert", "d", "--to", "ngp", "--out=" }, "--out is empty")]
        [TestCase(new[] { "convert", "d", "--to", "ngp", "--files", "move" }, "convert does not know the option --files")]
        public void UsageMistakes(string[] args, string error)
        {
            var p = ToolCommandLine.Parse(args);
            Assert.That(p.Errors, Has.Some.Contain(error));
        }

        [TestCase("help")]
        [TestCase("--help")]
        [TestCase("-h")]
        public void Help(string arg)
        {
            var p = ToolCommandLine.Parse(new[] { arg });
            Assert.That(p.Command, Is.EqualTo("help"));
            Assert.That(p.Errors, Is.Empty);
        }
    }
}
