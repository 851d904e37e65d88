using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>convert --to hdr-nerf</c>: exposure brackets made exactly from the capture's linear HDR colour
    /// (<c>hdr_path</c>, <see cref="HdrKeys"/>) in HDR-NeRF's synthetic layout (<see cref="HdrNerf"/>). Image k of a view
    /// is straight-alpha RGBA like the dataset's PNGs: the linear colour × <see cref="HdrNerf.ExposureTimes"/>[k], clipped
    /// to 1 and sRGB-encoded to the nearest code — the rule the PNG itself was made by, so k = 2 is the PNG — with the
    /// PNG's alpha. RGBA because the loader expects four channels (its half_res buffer, load_syn_llff.py:163) and
    /// composites with <c>--white_bkgd</c> as the Blender loaders do (run_nerf.py, the <c>syn_llff</c> branch:
    /// <c>images[...,:3]*images[...,-1:] + (1.-images[...,-1:])</c>, else <c>images[...,:3]</c>): a white background is
    /// radiance that saturates at every exposure, so compositing after the bracket is physically consistent. These are
    /// brackets of one linear image, not renders at each exposure: a camera response other than the sRGB curve, noise and
    /// blooming are not modelled.
    /// </summary>
    public static class HdrNerfExport
    {
        public static ConversionResult Write(ExportScene scene, string output, List<ValidationProblem> warnings, StagedOutput staged)
        {
            var root = scene.RootDirectory;
            var background = ProtocolBackground.For(root);
            // A solid protocol colour other than white or black has no HDR-NeRF flag: its loader composites over white or not at all.
            var splits = HdrNerf.Splits.Select(s => DatasetFolder.ReadSplit(root, s, DatasetReadMode.Strict)).ToList();
            Refusals(splits);
            if (scene.Frames.Any(f => f.Split == "val"))
                warnings.Add(new ValidationProblem("val", scene.Frames.Count(f => f.Split == "val") + " views", "are not exported: HDR-NeRF reads train and test only (load_syn_llff.py:85).", "Nothing to do; they stay in the dataset."));

            var written = new List<string>();
            var plans = new List<(string source, string stem, DatasetFrame frame)>();
            foreach (var split in splits)
                foreach (var frame in split.Frames)
                    plans.Add((frame.Named(HdrKeys.HdrPath).FullPath, split.Split + "/" + Path.GetFileNameWithoutExtension(frame.FilePath.Replace('\\', '/')), frame));
            foreach (var split in splits)
            {
                written.Add(Path.Combine(output, DatasetLayout.TransformsFileName(split.Split)));
                written.Add(Path.Combine(output, HdrNerf.ExposureFileName(split.Split)));
            }
            foreach (var plan in plans)
                for (var k = 0; k < HdrNerf.ExposureTimes.Length; k++) written.Add(Path.Combine(output, HdrNerf.ImagePath(plan.stem, k)));
            foreach (var path in written) DatasetConverter.EnsureAbsent(path);

            foreach (var split in splits)
            {
                var frames = new JArray();
                var exposures = new JObject();
                foreach (var plan in plans.Where(p => p.frame.File == split))
                {
                    frames.Add(new JObject { ["file_path"] = "./" + plan.stem, ["transform_matrix"] = JArray.FromObject(plan.frame.TransformMatrix.Value.ToRows()) });
                    var exr = ExrReader.Read(plan.source);
                    for (var k = 0; k < HdrNerf.ExposureTimes.Length; k++)
                    {
                        exposures["./" + HdrNerf.ImagePath(plan.stem, k)] = HdrNerf.ExposureTimes[k];
                        var rgba = Bracket(exr, HdrNerf.ExposureTimes[k]);
                        staged.WriteNewBytes(Path.Combine(output, HdrNerf.ImagePath(plan.stem, k)), PngWriter.Encode(rgba, exr.Width, exr.Height, PngPixelFormat.Rgba8));
                    }
                }
                var transforms = new JObject { ["camera_angle_x"] = split.CameraAngleX, ["frames"] = frames };
                staged.WriteNewText(Path.Combine(output, DatasetLayout.TransformsFileName(split.Split)), ExportJson.Serialise(transforms));
                staged.WriteNewText(Path.Combine(output, HdrNerf.ExposureFileName(split.Split)), ExportJson.Serialise(exposures));
            }
            warnings.Add(new ValidationProblem("exposure", string.Join(", ", HdrNerf.ExposureTimes.Select(t => ValidationProblem.Format(t))),
                "are the five exposure times, in units of the capture's own exposure (image _2 is the dataset's PNG); the brackets are the linear HDR colour scaled, clipped and sRGB-encoded, straight alpha like the PNGs.",
                "Nothing to do: HDR-NeRF learns its tone curve from them."));
            var white = background.R == 255 && background.G == 255 && background.B == 255;
            if (!white && (background.R | background.G | background.B) != 0)
                warnings.Add(new ValidationProblem("eval_protocol.json: background", background.Name, "is neither white nor black: HDR-NeRF composites over white (--white_bkgd) or keeps the colour as stored (black where alpha is 0).", "Train with --white_bkgd and score over white, or leave it out for black."));
            return new ConversionResult(output, output, written, warnings, new[] { "python3 run_nerf.py --config configs/demo.txt --dataset_type syn_llff --datadir " + output + (white ? " --white_bkgd" : "") + "   (HDR-NeRF; set near_depth for the scene)" });
        }

        /// <summary>One bracket, straight-alpha RGBA: linear colour × <paramref name="time"/>, clipped, encoded to the nearest sRGB code; alpha round(255a); (0, 0, 0, 0) where alpha is 0.</summary>
        public static byte[] Bracket(ExrImage exr, double time)
        {
            float[] red = exr.Channel("R"), green = exr.Channel("G"), blue = exr.Channel("B"), alpha = exr.Channel("A");
            var n = exr.Width * exr.Height;
            var rgba = new byte[n * 4];
            for (var i = 0; i < n; i++)
            {
                var a = (byte)Math.Floor(Math.Max(0, Math.Min(1, alpha[i])) * 255.0 + 0.5);
                if (a == 0) continue;
                rgba[4 * i] = Srgb.EncodeByteExact(Math.Min(1.0, red[i] * time));
                rgba[4 * i + 1] = Srgb.EncodeByteExact(Math.Min(1.0, green[i] * time));
                rgba[4 * i + 2] = Srgb.EncodeByteExact(Math.Min(1.0, blue[i] * time));
                rgba[4 * i + 3] = a;
            }
            return rgba;
        }

        /// <summary>Every view of train and test needs its linear colour: all missing ones are named before anything is written.</summary>
        static void Refusals(IReadOnlyList<DatasetSplitFile> splits)
        {
            var missing = new List<string>();
            foreach (var split in splits)
                foreach (var frame in split.Frames)
                {
                    var hdr = frame.Named(HdrKeys.HdrPath);
                    if (hdr == null || !hdr.Exists || frame.TransformMatrix == null) missing.Add(frame.FilePath ?? split.Split + " frame " + frame.Index);
                }
            if (splits.Any(s => s.Frames.Count == 0))
                throw new InvalidParameterException(new[] { new ValidationProblem("splits", string.Join(", ", splits.Where(s => s.Frames.Count == 0).Select(s => s.Split)), "has no views: HDR-NeRF trains on train and scores on test (load_syn_llff.py:85).", "Capture train and test views.") });
            if (missing.Count > 0)
                throw new InvalidParameterException(new[] { new ValidationProblem(HdrKeys.HdrPath, missing.Count + " of " + splits.Sum(s => s.Frames.Count) + " train/test views (first: " + missing[0] + ")",
                    "is missing: --to hdr-nerf makes the exposure brackets from each view's linear HDR colour (r_<i>_hdr.exr).",
                    "Capture with \"hdr\": { \"splits\": [\"train\", \"test\"] } (Outputs ▸ Linear HDR colour), or try nerf-dataset demo <dir> --preset hdr.") });
        }
    }
}
