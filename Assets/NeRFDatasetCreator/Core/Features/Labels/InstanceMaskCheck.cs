using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <b>instance vs mask</b>: the instance map's foreground is the mask's geometry — a pixel has an id exactly where the
    /// mask reads 128 or more, the threshold of the ids' majority rule (labels.md) — every id is one labels.json lists,
    /// and the semantic map is each pixel's instance class. Catches id maps shifted, flipped or blended at edges (a
    /// blend gives ids where less than half the pixel is covered, and ids between two objects' ids), maps drawn with
    /// other cull or alpha-clip rules than the mask, and instance/semantic maps out of step with labels.json.
    /// </summary>
    public sealed class InstanceMaskCheck : IViewCheck
    {
        public const string CheckName = "instance vs mask";

        /// <summary>
        /// Share of a view's geometry pixels (mask or id) allowed to disagree. Both maps come from the same samples by
        /// the same threshold, so exact data disagrees nowhere; a one-pixel shift moves the whole outline (≈ 2–5 % of a
        /// small object's pixels), a blend the edge pixels less than half covered.
        /// </summary>
        public const double MaxMismatch = 0.005;

        /// <summary>
        /// Share of a view's labelled pixels whose semantic id may differ from their instance's class: only a pixel shared
        /// by three objects can differ (two of one class outvote a third, labels.md's tie rule).
        /// </summary>
        public const double MaxSemanticMismatch = 0.01;

        readonly LabelTable _labels;
        readonly string _labelsProblem;
        int _views, _masked, _bad;
        double _worst, _worstSemantic;
        bool _problemReported;

        /// <param name="labels">The dataset's labels.json, or null with <paramref name="labelsProblem"/> saying why it cannot be read.</param>
        public InstanceMaskCheck(LabelTable labels, string labelsProblem)
        {
            _labels = labels;
            _labelsProblem = labelsProblem;
        }

        /// <summary>The check with the dataset's labels.json (read only when a frame names an instance map).</summary>
        public static InstanceMaskCheck For(string root, IReadOnlyList<CheckView> views)
        {
            if (!views.Any(v => v.InstanceFile != null)) return new InstanceMaskCheck(null, null);
            var path = Path.Combine(root, DatasetLayout.LabelsFileName);
            if (!File.Exists(path)) return new InstanceMaskCheck(null, "is missing, but frames name instance maps.");
            try
            {
                return new InstanceMaskCheck(LabelsJson.ReadFile(path), null);
            }
            catch (InvalidParameterException e)
            {
                return new InstanceMaskCheck(null, "cannot be read: " + e.Problems[0].Field + " " + e.Problems[0].Value + " " + e.Problems[0].Reason);
            }
        }

        public string Name => CheckName;

        public void View(CheckView view, CheckImages images, List<DatasetProblem> problems)
        {
            var ids = images.Instance;
            if (ids == null) return;
            _views++;
            if (_labels == null)
            {
                if (!_problemReported) problems.Add(new DatasetProblem(Name, DatasetLayout.LabelsFileName, -1, _labelsProblem + " The ids in the maps mean nothing without it."));
                _problemReported = true;
                _bad++;
                return;
            }
            var why = new List<string>();
            var known = _labels.Instances.Count;
            int unknown = 0, firstUnknown = 0;
            foreach (var id in ids)
                if (id > known)
                {
                    if (unknown++ == 0) firstUnknown = id;
                }
            if (unknown > 0)
                why.Add(unknown + " pixels hold ids labels.json does not list (e.g. " + firstUnknown + "; it lists 1–" + known + ")");

            var mask = images.Mask;
            if (mask != null)
            {
                _masked++;
                int missing = 0, extra = 0, geometry = 0;
                for (var i = 0; i < ids.Length; i++)
                {
                    var covered = mask[i] >= 128;
                    var labelled = ids[i] != 0;
                    if (mask[i] != 0 || labelled) geometry++;
                    if (covered && !labelled) missing++;
                    else if (!covered && labelled) extra++;
                }
                var fraction = geometry == 0 ? 0 : (double)(missing + extra) / geometry;
                if (fraction > _worst) _worst = fraction;
                if (fraction > MaxMismatch)
                    why.Add(CheckFigures.Percent(fraction) + " of the geometry disagrees with " + view.MaskFile + " (" + missing + " pixels covered at least half without an id, " +
                            extra + " covered less than half with one), above " + CheckFigures.Percent(MaxMismatch));
            }

            var semantic = images.Semantic;
            if (semantic != null)
            {
                var classes = _labels.ClassOfInstance;
                int labelled = 0, wrong = 0;
                for (var i = 0; i < ids.Length; i++)
                {
                    var expected = ids[i] < classes.Length ? classes[ids[i]] : 0;
                    if (expected == 0 && semantic[i] == 0) continue;
                    labelled++;
                    if (semantic[i] != expected) wrong++;
                }
                var share = labelled == 0 ? 0 : (double)wrong / labelled;
                if (share > _worstSemantic) _worstSemantic = share;
                if (share > MaxSemanticMismatch)
                    why.Add(CheckFigures.Percent(share) + " of the labelled pixels of " + view.SemanticFile + " are not their instance's class in labels.json, above " + CheckFigures.Percent(MaxSemanticMismatch));
            }
            if (why.Count == 0) return;
            _bad++;
            problems.Add(new DatasetProblem(Name, "./" + view.InstanceFile, view.Frame, string.Join("; ", why) +
                ": the id pass is offset, flipped, blended at edges or drawn with other cull rules, or the maps and labels.json are from different captures."));
        }

        public DatasetCheckResult Finish()
        {
            if (_views == 0) return DatasetCheckResult.Skip(Name, "no view has an instance map (a capture without labels)");
            if (_labels == null)
                return new DatasetCheckResult(Name, DatasetCheckStatus.Failed, _views + " views with instance maps, no readable " + DatasetLayout.LabelsFileName,
                    "every id in labels.json", DatasetLayout.LabelsFileName + " " + _labelsProblem);
            var figure = _views + " views" + (_masked > 0 ? ", worst mismatch with the mask " + CheckFigures.Percent(_worst) : ", none with a mask") +
                         ", worst semantic mismatch " + CheckFigures.Percent(_worstSemantic);
            return new DatasetCheckResult(Name, _bad > 0 ? DatasetCheckStatus.Failed : DatasetCheckStatus.Passed, figure,
                "≤ " + CheckFigures.Percent(MaxMismatch) + " of each view's geometry, ≤ " + CheckFigures.Percent(MaxSemanticMismatch) + " semantic, every id in labels.json",
                _bad > 0 ? _bad + " problem(s)" : null);
        }
    }
}
