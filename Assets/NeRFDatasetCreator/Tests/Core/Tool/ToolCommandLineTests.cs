using System.Linq;
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
            var options = (PlanCommand.Options)p.Options;
            Assert.That(options.ConfigPath, Is.EqualTo("s.json"));
            Assert.That(options.OutputFolder, Is.EqualTo("out/lego"));
        }

        [Test]
        public void OptionsWithEquals()
        {
            var p = ToolCommandLine.Parse(new[] { "plan", "--out=d", "--config=c.json" });
            Assert.That(p.Errors, Is.Empty);
            var options = (PlanCommand.Options)p.Options;
            Assert.That(options.ConfigPath, Is.EqualTo("c.json"));
            Assert.That(options.OutputFolder, Is.EqualTo("d"));
        }

        [Test]
        public void Validate()
        {
            var p = ToolCommandLine.Parse(new[] { "validate", "data/lego" });
            Assert.That(p.Errors, Is.Empty);
            Assert.That(p.Command, Is.EqualTo("validate"));
            Assert.That(((ValidateCommand.Options)p.Options).DatasetFolder, Is.EqualTo("data/lego"));
        }

        [Test]
        public void MergeCopiesByDefault()
        {
            var p = ToolCommandLine.Parse(new[] { "merge", "--out", "lego", "shards/shard-0", "shards/shard-1" });
            Assert.That(p.Errors, Is.Empty);
            Assert.That(p.Command, Is.EqualTo("merge"));
            var options = (MergeCommand.Options)p.Options;
            Assert.That(options.OutputFolder, Is.EqualTo("lego"));
            Assert.That(options.ShardFolders, Is.EqualTo(new[] { "shards/shard-0", "shards/shard-1" }));
            Assert.That(options.MoveFiles, Is.False);
        }

        [TestCase("copy", false)]
        [TestCase("move", true)]
        public void MergeFiles(string files, bool move)
        {
            var p = ToolCommandLine.Parse(new[] { "merge", "s0", "--files", files, "s1", "--out=lego" });
            Assert.That(p.Errors, Is.Empty);
            var options = (MergeCommand.Options)p.Options;
            Assert.That(options.MoveFiles, Is.EqualTo(move));
            Assert.That(options.ShardFolders, Is.EqualTo(new[] { "s0", "s1" }), "shard folders may come before, between and after options");
        }

        [TestCase("nerfstudio", ExportTarget.Nerfstudio)]
        [TestCase("colmap", ExportTarget.Colmap)]
        [TestCase("NGP", ExportTarget.Ngp)]
        public void Convert(string to, ExportTarget target)
        {
            var p = ToolCommandLine.Parse(new[] { "convert", "data/lego", "--to", to });
            Assert.That(p.Errors, Is.Empty);
            Assert.That(p.Command, Is.EqualTo("convert"));
            var options = (ConvertCommand.Options)p.Options;
            Assert.That(options.DatasetFolder, Is.EqualTo("data/lego"));
            Assert.That(options.Target, Is.EqualTo(target));
            Assert.That(options.OutputFolder, Is.Null, "the format's default place");
        }

        [Test]
        public void ConvertWithOut()
        {
            var p = ToolCommandLine.Parse(new[] { "convert", "--to=colmap", "--out", "exports/lego-colmap", "data/lego" });
            Assert.That(p.Errors, Is.Empty);
            var options = (ConvertCommand.Options)p.Options;
            Assert.That(options.OutputFolder, Is.EqualTo("exports/lego-colmap"));
            Assert.That(options.DatasetFolder, Is.EqualTo("data/lego"));
        }

        [Test]
        public void ConvertToColmapWithDepths_IsAFlagWithoutValue()
        {
            var p = ToolCommandLine.Parse(new[] { "convert", "data/lego", "--depths", "--to", "colmap" });
            Assert.That(p.Errors, Is.Empty);
            var options = (ConvertCommand.Options)p.Options;
            Assert.That(options.Depths, Is.True);
            Assert.That(options.DatasetFolder, Is.EqualTo("data/lego"), "--depths does not swallow the next argument");
            Assert.That(((ConvertCommand.Options)ToolCommandLine.Parse(new[] { "convert", "data/lego", "--to", "colmap" }).Options).Depths, Is.False);
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
        [TestCase(new[] { "convert", "d", "--to", "splat" }, "--to = splat: is not an export format. Use one of: nerfstudio, colmap, ngp, dynamic3dgs, gaussian-grouping, nerfies, dycheck, llff, dynerf, neus, replica, tum, multiscale, hdr-nerf, tensoir, gs-ir, r3dg, kubric, nsff, shape-of-motion (or the trainers' names 3dgs = gsplat = colmap, instant-ngp = ngp). Did you mean \"gsplat\"?")]
        [TestCase(new[] { "convert", "d", "--to", "3dg" }, "--to = 3dg: is not an export format. Use one of: nerfstudio, colmap, ngp, dynamic3dgs, gaussian-grouping, nerfies, dycheck, llff, dynerf, neus, replica, tum, multiscale, hdr-nerf, tensoir, gs-ir, r3dg, kubric, nsff, shape-of-motion (or the trainers' names 3dgs = gsplat = colmap, instant-ngp = ngp). Did you mean \"3dgs\"?")]
        [TestCase(new[] { "chek", "d" }, "unknown command 'chek'. Did you mean \"check\"?")]
        [TestCase(new[] { "--version", "check" }, "--version takes nothing after it ('check').")]
        [TestCase(new[] { "convert", "d", "--to", "ngp", "--out=" }, "--out is empty")]
        [TestCase(new[] { "convert", "d", "--to", "ngp", "--files", "move" }, "convert does not know the option --files")]
        public void UsageMistakes(string[] args, string error)
        {
            var p = ToolCommandLine.Parse(args);
            Assert.That(p.Errors, Has.Some.Contain(error));
        }

        /// <summary>The help text as released (0.x), word for word and space for space: the table's lines must add up to it.</summary>
        const string ReleasedUsage =
            "usage: nerf-dataset <command> [arguments]\n" +
            "  plan --config <settings.json> --out <dir>               the JSON files and a rig preview, no images\n" +
            "  validate <dir>                                          check a Blender-format dataset\n" +
            "  merge --out <dir> [--files copy|move] <shard-dir>...    join the folders of a sharded capture\n" +
            "  convert <dir> --to nerfstudio|colmap|ngp|dynamic3dgs|gaussian-grouping|nerfies|dycheck|llff|dynerf|neus|replica|tum|multiscale|hdr-nerf|tensoir|gs-ir|r3dg|kubric|nsff|shape-of-motion [--out <dir>] [--images copy|link|relative] [--depths] [--binary] [--points N] [--min-track N] [--object <name|id>] [--background white|black|random|protocol [--seed N]]  write a dataset in another trainer's format (--depths: colmap + 3DGS depth maps; --binary/--points/--min-track: the colmap model, tracks from depth; dynamic3dgs: multi-view dynamic captures; gaussian-grouping: object masks from the labels; --object: nerfstudio masks of one labelled object; llff, dynerf (N3DV, multi-view dynamic), neus: LLFF, 4DGaussians and NeuS layouts; replica, tum: RGB-D sequences of a monocular dynamic capture for SLAM; multiscale: gsplat's images_2/4/8 and mip-NeRF's multiscale layout; hdr-nerf: HDR-NeRF's exposure brackets from a capture with hdr; tensoir (also NeRFactor), gs-ir, r3dg: inverse-rendering layouts with albedo, normals, roughness and relit views; kubric, nsff: Kubric/MOVi and NSFF scenes with the optical flow of flow/; shape-of-motion: Shape of Motion's iPhone layout with the exact tracks of flow/)\n" +
            "  clean <dir> [--dry-run]                                 finish or roll back interrupted runs, remove their leftover folders\n" +
            "  check <dir> [--split S] [--json FILE] [--max-views N] [--model <dir>]  decode the images and check that alpha, masks, depth, normals, poses and point cloud agree\n" +
            "  evaluate <dir> --renders <dir> [--inverse <dir>] [--split test|sparse_<n>] [--out <dir>] [--layout 3dgs|nerfstudio|ngp|nerf-pytorch|plain] [--background white|black|dataset [--override-protocol]] [--trainer-metrics <json>] [--render-depth z|ray] [--geometry <recon.ply|.obj|folder> [--gt-mesh <mesh>] [--threshold <units>] [--step <k>]]  score a trainer's renders (PSNR, SSIM, depth, normals, Chamfer/F-score): metrics.json, error maps, report.html\n" +
            "  splits <dir> [--views 8[,3,...]]                        write sparse-view split files (splits/sparse_<n>.json: nerf_synthetic's paper lists, else farthest-point views) for evaluate --split\n" +
            "  demo <dir> [--preset static|dynamic|labels|lens|exposure|blur|monocular|hdr|materials|relight|flow] [--views N] [--size PX] [--renders-for <dataset>]  write a small trainable dataset of a built-in scene, no Unity needed (--renders-for: stand-in renders of a demo's test split, to try evaluate)\n" +
            "  place-splat <dir> --model <trained output> [--trainer 3dgs|nerfstudio|gsplat] [--ply <file>] [--json <file>]  where a trained Gaussian splat goes in the Unity scene: Transform, object-to-world, cameras.json\n" +
            "  flow <dir> [--spans 1[,2,...]] [--no-backward] [--no-scene-flow] [--tracks Q[,Q,...]] [--stride N] [--threads N]  add exact optical flow, scene flow, occlusion and tracks (flow/) to a dynamic dataset with \"geometryPack\": \"everyStep\"\n" +
            "exit codes: 0 success; 1 problems found, refused or failed; 2 usage, config or settings error\n" +
            "nerf-dataset <command> --help prints that command's options; nerf-dataset --version its version.";

        [Test]
        public void TheHelpTextIsBuiltFromTheCommandTableAsReleased()
        {
            Assert.That(ToolCommands.Usage, Is.EqualTo(ReleasedUsage));
            Assert.That(ToolCommands.All.Select(c => c.Name), Is.EqualTo(new[] { "plan", "validate", "merge", "convert", "clean", "check", "evaluate", "splits", "demo", "place-splat", "flow" }));
        }

        [Test]
        public void EveryCommandInTheTableIsFoundByItsNameAndParsesIntoItsOwnOptions()
        {
            foreach (var command in ToolCommands.All)
            {
                Assert.That(ToolCommands.Find(command.Name), Is.SameAs(command));
                Assert.That(ToolCommandLine.Parse(new[] { command.Name }).Command, Is.EqualTo(command.Name));
            }
            Assert.That(ToolCommands.Find("Check"), Is.Null, "command names are case-sensitive");
            Assert.That(ToolCommandLine.Parse(new[] { "check", "d" }).Options, Is.TypeOf<CheckCommand.Options>());
            Assert.That(ToolCommandLine.Parse(new[] { "evaluate", "d", "--renders", "r" }).Options, Is.TypeOf<EvaluationOptions>());
        }

        /// <summary><c>--split</c> is read by one parser: the same names, the same refusal, in check and evaluate.</summary>
        [TestCase("check", "training")]
        [TestCase("check", "Train")]
        [TestCase("evaluate", "TEST")]
        [TestCase("evaluate", "all")]
        public void SplitIsRefusedTheSameWayByEveryCommand(string command, string split)
        {
            var args = command == "evaluate" ? new[] { command, "d", "--renders", "r", "--split", split } : new[] { command, "d", "--split", split };
            var p = ToolCommandLine.Parse(args);
            Assert.That(p.Errors, Is.EqualTo(new[] { "--split = " + split + ": is not train, val or test." }));
        }

        [TestCase("train")]
        [TestCase("val")]
        [TestCase("test")]
        public void SplitNamesAreReadTheSameWayByEveryCommand(string split)
        {
            Assert.That(((CheckCommand.Options)ToolCommandLine.Parse(new[] { "check", "d", "--split", split }).Options).Split, Is.EqualTo(split));
            Assert.That(((EvaluationOptions)ToolCommandLine.Parse(new[] { "evaluate", "d", "--renders", "r", "--split", split }).Options).Split, Is.EqualTo(split));
        }

        [Test]
        public void AFlagOfOneCommandIsNeverReadAsTakingAValueByAnother()
        {
            // --dry-run is clean's, --depths convert's: validate refuses them without swallowing the folder after them.
            var p = ToolCommandLine.Parse(new[] { "validate", "--dry-run", "d" });
            Assert.That(p.Errors, Is.EqualTo(new[] { "validate does not know the option --dry-run." }));
            Assert.That(((ValidateCommand.Options)p.Options).DatasetFolder, Is.EqualTo("d"));
        }

        [Test]
        public void ConfigLoaderNamesParseAsTheirExports()
        {
            Assert.That(((ConvertCommand.Options)ToolCommandLine.Parse(new[] { "convert", "d", "--to", "3dgs" }).Options).Target, Is.EqualTo(ExportTarget.Colmap));
            Assert.That(((ConvertCommand.Options)ToolCommandLine.Parse(new[] { "convert", "d", "--to", "instant-ngp" }).Options).Target, Is.EqualTo(ExportTarget.Ngp));
            // --depths and the COLMAP model options belong to colmap, whichever name chose it.
            Assert.That(ToolCommandLine.Parse(new[] { "convert", "d", "--to", "3dgs", "--depths", "--binary" }).Errors, Is.Empty);
        }

        [Test]
        public void EveryCommandsUsageNamesOnlyItselfAndListsAnOptionLinePerOptionItTakes()
        {
            foreach (var command in ToolCommands.All)
            {
                var lines = command.Usage.Split('\n');
                Assert.That(lines[0], Is.EqualTo("usage: nerf-dataset " + command.Synopsis));
                Assert.That(lines[1], Is.EqualTo(command.Summary));
                Assert.That(lines[lines.Length - 1], Is.EqualTo(ToolCommands.ExitCodes));
                foreach (var other in ToolCommands.All.Where(c => c != command))
                    Assert.That(command.Usage, Does.Not.Contain(other.HelpLine), command.Name + "'s usage holds " + other.Name + "'s table line");
            }
        }

        [TestCase("--version")]
        public void Version(string arg)
        {
            var p = ToolCommandLine.Parse(new[] { arg });
            Assert.That(p.Command, Is.EqualTo("version"));
            Assert.That(p.Errors, Is.Empty);
            Assert.That(ToolCommands.VersionLine, Is.EqualTo("nerf-dataset " + PluginInfo.Version));
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
