using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Recognises nerf_synthetic's camera rig: 100 train views at the poses of its <c>transforms_train.json</c> and 200
    /// test views. Only then do the sparse-view papers' index lists (<see cref="SparseViewLists"/>) mean the views they
    /// meant. The train centres are compared after removing position and scale (each set minus its mean, divided by its
    /// RMS distance from it), so a Unity capture of the same rig, recentred or rescaled by the dataset's normalisation,
    /// is recognised; every centre must lie within <see cref="Tolerance"/> (in RMS units) of nerf_synthetic's.
    /// The test poses are not compared (only the count): the test lists are every n-th view of the file.
    /// </summary>
    public static class NerfSyntheticRig
    {
        public const int TrainViews = 100;
        public const int TestViews = 200;

        /// <summary>How far (in units of the rig's RMS radius about its mean centre) a train centre may lie from nerf_synthetic's.</summary>
        public const double Tolerance = 1e-3;

        /// <summary>Whether the train centres (in file order) and the test count are nerf_synthetic's rig.</summary>
        public static bool Matches(IReadOnlyList<Vector3d> trainCentres, int testViews)
        {
            if (trainCentres == null || trainCentres.Count != TrainViews || testViews != TestViews) return false;
            var ours = Standardise(trainCentres);
            var theirs = Standardise(Reference());
            if (ours == null || theirs == null) return false;
            for (var i = 0; i < TrainViews; i++)
                if (Vector3d.Distance(ours[i], theirs[i]) > Tolerance) return false;
            return true;
        }

        /// <summary>Each centre minus the mean, over the RMS distance from the mean; null when all coincide.</summary>
        static Vector3d[] Standardise(IReadOnlyList<Vector3d> centres)
        {
            var mean = Vector3d.Zero;
            foreach (var c in centres) mean += c;
            mean /= centres.Count;
            var sum = 0.0;
            foreach (var c in centres) sum += (c - mean).LengthSquared;
            var rms = Math.Sqrt(sum / centres.Count);
            if (!(rms > 0) || double.IsInfinity(rms)) return null;
            var result = new Vector3d[centres.Count];
            for (var i = 0; i < centres.Count; i++) result[i] = (centres[i] - mean) / rms;
            return result;
        }

        /// <summary>
        /// nerf_synthetic lego's train camera centres, r_0 … r_99, as unit vectors (all lie at radius 4.0311 about the
        /// origin), rounded to 1e-5: from transforms_train.json (the NeRF authors' data, CC BY 3.0; the same file is
        /// Tests/Core/Fixtures/nerf_synthetic_lego/transforms_train.json, and the tests check this table against it).
        /// </summary>
        public static IReadOnlyList<Vector3d> Reference()
        {
            var result = new Vector3d[TrainViews];
            for (var i = 0; i < TrainViews; i++) result[i] = new Vector3d(Directions[3 * i], Directions[3 * i + 1], Directions[3 * i + 2]);
            return result;
        }

        static readonly double[] Directions =
        {
            -0.01335, 0.95394, 0.29969, -0.34696, 0.88170, 0.31972, -0.83984, -0.41495, 0.34999, -0.30920, -0.40611, 0.85993,
            0.71606, 0.62345, 0.31396, -0.71709, 0.08795, 0.69141, 0.55389, -0.48280, 0.67832, -0.03220, -0.06829, 0.99715,
            -0.93016, -0.15076, 0.33478, -0.86583, 0.20780, 0.45513, -0.83231, -0.50919, 0.21904, 0.13125, 0.58493, 0.80040,
            -0.12094, 0.49395, 0.86104, 0.52960, -0.82966, 0.17661, -0.48585, 0.03091, 0.87350, 0.65833, 0.62163, 0.42447,
            -0.79133, -0.10404, 0.60247, 0.92388, -0.27640, 0.26468, 0.23837, 0.02335, 0.97089, 0.78589, -0.53888, 0.30330,
            0.47430, -0.74109, 0.47521, -0.19814, -0.42102, 0.88515, 0.70718, 0.36662, 0.60455, -0.70853, 0.37472, 0.59797,
            -0.52115, -0.63695, 0.56806, 0.90233, 0.14752, 0.40502, 0.21757, 0.95980, 0.17732, -0.10437, 0.74373, 0.66028,
            0.52387, -0.66434, 0.53312, -0.39981, -0.79410, 0.45778, 0.42973, 0.12862, 0.89375, -0.32179, 0.05049, 0.94546,
            -0.97736, -0.00006, 0.21158, 0.41084, -0.45636, 0.78927, -0.55755, 0.64516, 0.52240, -0.83939, 0.36393, 0.40370,
            0.43578, -0.51873, 0.73554, 0.21789, 0.11396, 0.96930, -0.52113, 0.76436, 0.37970, -0.03463, 0.42034, 0.90670,
            -0.82923, 0.40400, 0.38622, -0.10347, 0.97485, 0.19739, 0.11767, 0.97988, 0.16123, 0.48364, -0.36477, 0.79564,
            -0.45628, -0.26054, 0.85084, -0.64232, 0.43354, 0.63203, 0.00187, -0.70221, 0.71196, 0.10457, 0.24009, 0.96510,
            0.00370, -0.28465, 0.95863, 0.35581, -0.14347, 0.92348, 0.28201, 0.72905, 0.62367, -0.51242, 0.81706, 0.26426,
            -0.74477, -0.51935, 0.41902, -0.96409, -0.20492, 0.16893, -0.82533, 0.26021, 0.50112, 0.35070, -0.91069, 0.21827,
            -0.15453, 0.10730, 0.98214, 0.08434, 0.44118, 0.89345, -0.57434, 0.20285, 0.79309, 0.78589, 0.23070, 0.57371,
            -0.67818, 0.70347, 0.21261, -0.00518, 0.67507, 0.73773, -0.29086, 0.07881, 0.95352, 0.57510, -0.74951, 0.32787,
            -0.20533, 0.96381, 0.17003, 0.19495, -0.96099, 0.19620, -0.41762, 0.42196, 0.80470, -0.00492, 0.86951, 0.49389,
            0.72857, -0.44536, 0.52043, -0.96057, -0.22966, 0.15673, 0.25857, -0.91652, 0.30517, -0.22643, -0.69953, 0.67778,
            0.88684, -0.30731, 0.34506, 0.64241, -0.54459, 0.53920, 0.63161, 0.66141, 0.40449, -0.19668, 0.96555, 0.17037,
            -0.06103, -0.91834, 0.39107, 0.40907, 0.13041, 0.90313, -0.72060, 0.64915, 0.24360, 0.01809, 0.48472, 0.87448,
            0.62729, -0.26738, 0.73145, -0.42504, 0.84893, 0.31412, -0.10217, 0.29819, 0.94902, -0.87573, 0.04250, 0.48092,
            0.17169, -0.64192, 0.74730, -0.97590, 0.13986, 0.16754, 0.28886, -0.37985, 0.87879, -0.50623, -0.25129, 0.82497,
            -0.00113, 0.01723, 0.99985, -0.08922, -0.97420, 0.20731, -0.85252, -0.07220, 0.51768, 0.05218, -0.28247, 0.95786,
            -0.34622, -0.55298, 0.75786, -0.46103, -0.25017, 0.85139, -0.73472, 0.39875, 0.54880, 0.88412, -0.44983, 0.12643,
            -0.74620, 0.44793, 0.49249, -0.86749, 0.07423, 0.49189, -0.07702, -0.92560, 0.37058, 0.52172, -0.25609, 0.81378,
        };
    }
}
