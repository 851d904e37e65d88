using System;
using System.Diagnostics;
using System.IO;
using System.Runtime.InteropServices;
using System.Threading.Tasks;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Issue 32 item 8: only regular files, sized before they are read — a real FIFO (which blocks whoever opens it),
    /// the real /dev/zero (which never ends) and a sparse 3 GB file (no real disk use).
    /// </summary>
    public class ReadableFileTests
    {
        static void AssumeUnix() =>
            Assume.That(RuntimeInformation.IsOSPlatform(OSPlatform.Linux) || RuntimeInformation.IsOSPlatform(OSPlatform.OSX), "FIFOs and /dev/zero are Unix's");

        /// <summary>A real FIFO made by mkfifo(1).</summary>
        internal static string MakeFifo(string path)
        {
            var start = new ProcessStartInfo("mkfifo", "\"" + path + "\"") { UseShellExecute = false };
            using (var process = Process.Start(start))
            {
                process.WaitForExit();
                Assert.That(process.ExitCode, Is.EqualTo(0), "mkfifo " + path);
            }
            return path;
        }

        /// <summary>Runs <paramref name="read"/> on another thread: a read that opens the FIFO blocks forever, and the test must still end.</summary>
        static Exception Outcome(Action read)
        {
            var task = Task.Run(read);
            try
            {
                Assert.That(task.Wait(TimeSpan.FromSeconds(60)), Is.True, "the read blocked (it opened the FIFO)");
            }
            catch (AggregateException e)
            {
                return e.InnerException;
            }
            return null;
        }

        [Test]
        public void DotNetSaysNormalForAFifoSoItsAttributesCannotTellItFromAFile()
        {
            // The premise of ReadableFile: no FileAttributes flag marks a FIFO or a device on .NET (Linux), so the size must.
            AssumeUnix();
            using (var temp = new TempFolder())
            {
                var fifo = MakeFifo(temp.Combine("fifo"));
                var regular = temp.Combine("file.txt");
                File.WriteAllText(regular, "x");
                Assert.That(File.GetAttributes(fifo), Is.EqualTo(File.GetAttributes(regular)));
                Assert.That(new FileInfo(fifo).Length, Is.EqualTo(0));
                Assert.That(new FileInfo("/dev/zero").Length, Is.EqualTo(0));
            }
        }

        [Test]
        public void AFifoIsRefusedUnopenedByEveryRead()
        {
            AssumeUnix();
            using (var temp = new TempFolder())
            {
                var fifo = MakeFifo(temp.Combine("transforms_val.json"));
                foreach (var read in new Action[]
                         {
                             () => FileOps.ReadText(fifo),
                             () => FileOps.OpenText(fifo).Dispose(),
                             () => PngReader.Read(fifo),
                             () => ReadableFile.ReadAllBytes(fifo, 100),
                         })
                {
                    var e = Outcome(read);
                    Assert.That(e, Is.InstanceOf<IOException>());
                    Assert.That(e.Message, Is.EqualTo(fifo + " " + ReadableFile.EmptyReason));
                }
            }
        }

        [Test]
        public void DevZeroIsRefusedUnread()
        {
            AssumeUnix();
            var e = Outcome(() => PngReader.Read("/dev/zero"));
            Assert.That(e, Is.InstanceOf<IOException>());
            Assert.That(e.Message, Does.StartWith("/dev/zero is empty (0 bytes) or is not a regular file"));
            Assert.That(Outcome(() => FileOps.ReadText("/dev/zero")).Message, Does.StartWith("/dev/zero "));
        }

        [Test]
        public void ASparse3GbFileIsRefusedByItsSizeBeforeAByteIsRead()
        {
            using (var temp = new TempFolder())
            {
                var path = temp.Combine("transforms_val.json");
                using (var file = new FileStream(path, FileMode.CreateNew)) file.SetLength(3L << 30); // sparse: no blocks written
                var streamed = Assert.Throws<FileTooLargeException>(() => FileOps.OpenText(path).Dispose());
                Assert.That(streamed.Message, Is.EqualTo(path + " is 3 GiB, more than the 512 MiB read whole for a file of this kind (this plugin's largest are a few hundred MB), so it is refused unread."));
                Assert.Throws<FileTooLargeException>(() => FileOps.ReadText(path));
                Assert.Throws<FileTooLargeException>(() => PngReader.Read(path));
            }
        }

        [Test]
        public void AStreamEndsAtTheSizeTheFileHadWhenItWasOpened()
        {
            using (var temp = new TempFolder())
            {
                var path = temp.Combine("a.bin");
                File.WriteAllBytes(path, new byte[] { 1, 2, 3 });
                using (var stream = ReadableFile.OpenRead(path, 100))
                {
                    using (var more = new FileStream(path, FileMode.Append, FileAccess.Write, FileShare.ReadWrite)) more.Write(new byte[] { 4, 5 }, 0, 2);
                    var buffer = new byte[10];
                    var total = 0;
                    int n;
                    while ((n = stream.Read(buffer, total, buffer.Length - total)) > 0) total += n;
                    Assert.That(total, Is.EqualTo(3));
                    Assert.That(stream.Length, Is.EqualTo(3));
                }
                Assert.That(ReadableFile.ReadAllBytes(path, 100), Is.EqualTo(new byte[] { 1, 2, 3, 4, 5 }));
                Assert.That(Assert.Throws<FileTooLargeException>(() => ReadableFile.ReadAllBytes(path, 4)).Length, Is.EqualTo(5));
                Assert.That(Assert.Throws<UnreadableFileException>(() => ReadableFile.Length(temp.Path, 100)).Reason, Is.EqualTo("is a folder, not a file."));
            }
        }
    }
}
