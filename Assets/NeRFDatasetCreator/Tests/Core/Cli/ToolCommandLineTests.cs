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

        [TestCase(new string[0], "no command")]
        [TestCase(new[] { "render" }, "unknown command 'render'")]
        [TestCase(new[] { "plan", "--config", "s.json" }, "plan needs --out")]
        [TestCase(new[] { "plan", "--out", "d" }, "plan needs --config")]
        [TestCase(new[] { "plan", "--config" }, "--config needs a value")]
        [TestCase(new[] { "plan", "--config", "a", "--config", "b", "--out", "d" }, "given twice")]
        [TestCase(new[] { "plan", "--config", "a", "--out", "d", "--fast", "yes" }, "does not know the option --fast")]
        [TestCase(new[] { "validate" }, "exactly one dataset folder")]
        [TestCase(new[] { "validate", "a", "b" }, "exactly one dataset folder")]
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
