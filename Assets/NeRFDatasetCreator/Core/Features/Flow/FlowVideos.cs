using System;
using System.Collections.Generic;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Which videos a dynamic dataset holds (Documentation~/flow.md, "What a video is"). Monocular: the train split, one
    /// view per time step, matched to the geometry pack's step by its <c>time</c>; val and test views sit between steps
    /// and get no flow. Multi-view: one video per split and <c>camera_id</c>, test cameras included, frames ordered by
    /// <c>time_step</c>. Every frame needs its step's mesh in the geometry pack (<c>"geometryPack": "everyStep"</c>).
    /// </summary>
    public static class FlowVideos
    {
        /// <summary>How far a monocular view's time may be from its step's recorded time (both are written at round-trip precision).</summary>
        public const double TimeTolerance = 1e-9;

        public static IReadOnlyList<FlowVideo> Of(ExportScene scene, IReadOnlyList<GeometryPackEntry> steps)
        {
            if (!scene.Frames.Any(f => f.Time.HasValue))
                throw Refuse("time", "none (a static dataset)", "has no time: flow is the motion of the target between time steps.",
                    "Capture with time.mode \"monocular\" or \"multi-view\" and \"geometryPack\": \"everyStep\" (Documentation~/flow.md).");
            var byStep = new Dictionary<int, GeometryPackEntry>();
            foreach (var e in steps)
                if (e.Step.HasValue && e.Problem == null) byStep[e.Step.Value] = e;
            if (byStep.Count < 2)
                throw Refuse("geometry", byStep.Count + " per-step meshes", "are recorded in dataset_config.json, but flow needs the target's mesh at every time step.",
                    "Capture with \"geometryPack\": \"everyStep\" (Documentation~/flow.md).");

            var multiView = scene.Frames.All(f => f.Timing.Camera.HasValue && f.Timing.Step.HasValue);
            var videos = new List<FlowVideo>();
            if (!multiView)
            {
                var frames = new List<FlowVideoFrame>();
                foreach (var f in scene.Split("train"))
                {
                    if (!f.Time.HasValue) throw Refuse("time", f.ImagePath, "has no time key.", "Re-capture the dataset in one time mode.");
                    var step = byStep.Values.FirstOrDefault(e => e.Time.HasValue && Math.Abs(e.Time.Value - f.Time.Value) <= TimeTolerance);
                    if (step == null)
                        throw Refuse("time", f.ImagePath + " at time " + ValidationProblem.Format(f.Time.Value),
                            "matches no step of the geometry pack, so the mesh it sees is unknown.", "Capture with \"geometryPack\": \"everyStep\" in the same run as the images.");
                    frames.Add(new FlowVideoFrame(f, step.Step.Value, step.File));
                }
                if (frames.Count >= 2) videos.Add(new FlowVideo(FlowLayout.MonocularVideo, "train", null, frames));
            }
            else
            {
                foreach (var split in DatasetSplits.Names)
                    foreach (var camera in scene.Split(split).GroupBy(f => f.Timing.Camera.Value).OrderBy(g => g.Key))
                    {
                        var frames = new List<FlowVideoFrame>();
                        foreach (var f in camera.OrderBy(f => f.Timing.Step.Value))
                        {
                            if (!byStep.TryGetValue(f.Timing.Step.Value, out var step))
                                throw Refuse("time_step", f.ImagePath + " at step " + f.Timing.Step.Value,
                                    "has no mesh in the geometry pack.", "Capture with \"geometryPack\": \"everyStep\" in the same run as the images.");
                            if (frames.Count > 0 && frames[frames.Count - 1].Step == step.Step.Value)
                                throw Refuse("time_step", f.ImagePath, "is camera " + camera.Key + " at step " + step.Step.Value + " again: a video has one view per step.",
                                    "Re-capture the split (nerf-dataset validate lists what is wrong).");
                            frames.Add(new FlowVideoFrame(f, step.Step.Value, step.File));
                        }
                        if (frames.Count >= 2) videos.Add(new FlowVideo(FlowLayout.MultiViewVideo(split, camera.Key), split, camera.Key, frames));
                    }
            }
            if (videos.Count == 0)
                throw Refuse("splits", "no video of two or more views", "is in the dataset: flow is between the views of one camera path at two time steps.",
                    "Capture at least two time steps.");
            return videos;
        }

        static InvalidParameterException Refuse(string field, string value, string reason, string fix) =>
            new InvalidParameterException(new[] { new ValidationProblem(field, value, reason, fix) });
    }
}
