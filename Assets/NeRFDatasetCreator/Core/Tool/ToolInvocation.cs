using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>The parsed command line of the <c>nerf-dataset</c> tool.</summary>
    public sealed class ToolInvocation
    {
        public const string PlanCommand = "plan";
        public const string ValidateCommand = "validate";
        public const string MergeCommand = "merge";
        public const string ConvertCommand = "convert";
        public const string CleanCommand = "clean";
        public const string EvaluateCommand = "evaluate";
        public const string CheckCommand = "check";
        public const string HelpCommand = "help";

        /// <summary>"plan", "validate", "merge", "convert", "clean", "check", "evaluate" or "help".</summary>
        public string Command { get; internal set; }

        /// <summary><c>plan --config &lt;file&gt;</c>.</summary>
        public string ConfigPath { get; internal set; }

        /// <summary>
        /// <c>--out &lt;dir&gt;</c>: the dataset folder <c>plan</c> and <c>merge</c> create; for <c>convert</c> the folder
        /// the export goes to, null for the format's default place inside the dataset.
        /// </summary>
        public string OutputFolder { get; internal set; }

        /// <summary><c>validate &lt;dir&gt;</c> and <c>convert &lt;dir&gt;</c>: the Blender-format dataset to read; <c>clean &lt;dir&gt;</c>: the folder to clean.</summary>
        public string DatasetFolder { get; internal set; }

        /// <summary><c>merge … &lt;shard-dir&gt;…</c>: the shard folders, in the order given.</summary>
        public List<string> ShardFolders { get; } = new List<string>();

        /// <summary><c>merge --files move</c>: move the images out of the shard folders instead of copying them.</summary>
        public bool MoveFiles { get; internal set; }

        /// <summary><c>clean --dry-run</c>: list the leftovers without changing anything.</summary>
        public bool DryRun { get; internal set; }

        /// <summary><c>convert --to nerfstudio|colmap|ngp|dynamic3dgs</c>.</summary>
        public ExportTarget? Target { get; internal set; }

        /// <summary><c>convert --to nerfstudio --object &lt;name|id&gt;</c>: mask every frame to this labelled object; null for none.</summary>
        public string ObjectName { get; internal set; }

        /// <summary><c>convert --to colmap --depths</c>: also write 3DGS's inverse-depth maps and depth_params.json.</summary>
        public bool Depths { get; internal set; }

        /// <summary><c>convert --to colmap --binary</c>: cameras.bin, images.bin, points3D.bin instead of the text model.</summary>
        public bool Binary { get; internal set; }

        /// <summary><c>convert --to colmap --points N</c>: the first N points of points3d.ply; null = all.</summary>
        public int? ColmapPoints { get; internal set; }

        /// <summary><c>convert --to colmap --min-track N</c>: null = <see cref="ColmapOptions.DefaultMinTrackLength"/>.</summary>
        public int? MinTrackLength { get; internal set; }

        /// <summary>The COLMAP model options given, or null when none was.</summary>
        public ColmapOptions ColmapModelOptions => Binary || ColmapPoints.HasValue || MinTrackLength.HasValue
            ? new ColmapOptions(Binary, ColmapPoints, MinTrackLength ?? ColmapOptions.DefaultMinTrackLength)
            : null;

        /// <summary><c>evaluate &lt;dir&gt; --renders &lt;dir&gt; …</c>: what to score and how.</summary>
        public EvaluationOptions Evaluation { get; internal set; }

        /// <summary><c>check --split train|val|test</c>: only that split; null for all.</summary>
        public string Split { get; internal set; }

        /// <summary><c>check --json &lt;file&gt;</c>: where to write the whole report (a file that must not exist yet).</summary>
        public string JsonReport { get; internal set; }

        /// <summary><c>check --max-views N</c>: at most N views per split, spread evenly; 0 for all.</summary>
        public int MaxViews { get; internal set; }

        /// <summary>Usage mistakes; the command runs only when this is empty.</summary>
        public List<string> Errors { get; } = new List<string>();

        /// <summary>What <c>--help</c> prints: one line per command, then the exit codes.</summary>
        public const string Usage =
            "usage: nerf-dataset <command> [arguments]\n" +
            "  plan --config <settings.json> --out <dir>               the JSON files and a rig preview, no images\n" +
            "  validate <dir>                                          check a Blender-format dataset\n" +
            "  merge --out <dir> [--files copy|move] <shard-dir>...    join the folders of a sharded capture\n" +
            "  convert <dir> --to nerfstudio|colmap|ngp|dynamic3dgs|gaussian-grouping [--out <dir>] [--depths] [--binary] [--points N] [--min-track N] [--object <name|id>]  write a dataset in another trainer's format (--depths: colmap + 3DGS depth maps; --binary/--points/--min-track: the colmap model, tracks from depth; dynamic3dgs: multi-view dynamic captures; gaussian-grouping: object masks from the labels; --object: nerfstudio masks of one labelled object)\n" +
            "  clean <dir> [--dry-run]                                 finish or roll back interrupted runs, remove their leftover folders\n" +
            "  check <dir> [--split S] [--json FILE] [--max-views N]   decode the images and check that alpha, masks, depth, normals, poses and point cloud agree\n" +
            "  evaluate <dir> --renders <dir> [--split test] [--out <dir>] [--layout 3dgs|nerfstudio|ngp|plain] [--background white|black|dataset] [--render-depth z|ray] [--geometry <recon.ply|.obj|folder> [--gt-mesh <mesh>] [--threshold <units>] [--step <k>]]  score a trainer's renders (PSNR, SSIM, depth, normals, Chamfer/F-score): metrics.json, error maps, report.html\n" +
            "exit codes: 0 success; 1 problems found, refused or failed; 2 usage, config or settings error";
    }
}
