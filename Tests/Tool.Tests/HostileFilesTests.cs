using System;
using System.Diagnostics;
using System.IO;
using System.Runtime.InteropServices;
using System.Threading.Tasks;
using NUnit.Framework;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary>
    /// Issue 32 items 5–11 through the tool: hostile files in a dataset (a FIFO, a character device, a sparse 3 GB
    /// split, lying PLY headers …) are problems naming the file — never a hang, never "ran out of memory".
    /// </summary>
    [TestFixture]
    public class HostileFilesTests
    {
        Scratch _scratch;
        string _dataset;

        [SetUp]
        public void SetUp()
        {
            _scratch = new Scratch();
            _dataset = RenderedDataset.Create(_scratch, "ds");
        }

        [TearDown]
        public void TearDown() => _scratch.Dispose();

        static void AssumeUnix() =>
            Assume.That(RuntimeInformation.IsOSPlatform(OSPlatform.Linux) || RuntimeInformation.IsOSPlatform(OSPlatform.OSX), "FIFOs and devices are Unix's");

        /// <summary>Runs a command of the tool (in this process) on another thread: a run that opens a FIFO waits forever, and the test must still end.</summary>
        internal static ToolRun Within(params string[] args)
        {
            var task = Task.Run(() => ToolRun.Of(args));
            Assert.That(task.Wait(TimeSpan.FromMinutes(3)), Is.True, "'" + string.Join(" ", args) + "' hung");
            return task.Result;
        }

        internal static void Run(string file, string arguments)
        {
            using (var process = Process.Start(new ProcessStartInfo(file, arguments) { UseShellExecute = false }))
            {
                process.WaitForExit();
                Assume.That(process.ExitCode, Is.EqualTo(0), file + " " + arguments);
            }
        }

        [Test]
        public void AFifoInPlaceOfAnImageIsAProblemNamingItInCheckAndValidate()
        {
            AssumeUnix();
            var image = Path.Combine(_dataset, "train", "r_0.png");
            File.Delete(image);
            Run("mkfifo", "\"" + image + "\"");
            foreach (var command in new[] { "check", "validate" })
            {
                var run = Within(command, _dataset);
                Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
                Assert.That(run.Out, Does.Contain(image + " is empty (0 bytes) or is not a regular file (a pipe or device reports no size), so it is not read."), command);
            }
        }

        [Test]
        public void ACharacterDeviceInPlaceOfAnImageIsAProblemNotOutOfMemory()
        {
            // A device like /dev/zero (char 1,5) inside the dataset: a symbolic link to /dev/zero leaves the dataset and is refused as such.
            AssumeUnix();
            var image = Path.Combine(_dataset, "train", "r_0.png");
            File.Delete(image);
            Run("mknod", "\"" + image + "\" c 1 5"); // needs root, as the CI runs; skipped otherwise
            var run = Within("check", _dataset);
            Assert.That(run.ExitCode, Is.EqualTo(1), run.ToString());
            Assert.That(run.Out, Does.Contain("./train/r_0.png frame 0 [dataset]: cannot be decoded as the colour image: " + image + " is empty (0 bytes) or is not a regular file"));
        }

        [Test]
        public void ASparse3GbSplitIsRefusedByItsSizeInCheckAndValidate()
        {
            var val = Path.Combine(_dataset, "transforms_val.json");
            // The real split, then a sparse tail of zero bytes to 3 GiB (no disk used): JSON readers stop at the object's end.
            using (var file = new FileStream(val, FileMode.Open)) file.SetLength(3L << 30);
            var reason = "is 3 GiB, more than the 512 MiB read whole for a file of this kind (this plugin's largest are a few hundred MB), so it is refused unread.";
            var check = Within("check", _dataset);
            Assert.That(check.ExitCode, Is.EqualTo(1), check.ToString());
            Assert.That(check.Out, Does.Contain("problem: transforms_val.json [dataset]: cannot be read: " + val + " " + reason));
            var validate = Within("validate", _dataset);
            Assert.That(validate.ExitCode, Is.EqualTo(1), validate.ToString()); // validate's streaming read used to say OK
            Assert.That(validate.Out, Does.Contain("problem: transforms_val.json: " + reason));
        }
    }
}
