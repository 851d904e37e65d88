using System;
using System.Collections.Generic;
using System.IO;
using UnityEngine;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>Small captures of the test sphere for the editor-session tests, and what they compare before and after.</summary>
    static class SessionTestSupport
    {
        public static CaptureOptions Options() => new CaptureOptions
        {
            Width = 16,
            Height = 16,
            Supersampling = 1,
            VerticalFieldOfViewDegrees = 40,
            NearClip = 0.1,
            FarClip = 100,
        };

        /// <summary><paramref name="count"/> cameras on a circle of radius 3 around the origin, looking at it.</summary>
        public static List<UnityPose> Poses(int count)
        {
            var poses = new List<UnityPose>();
            for (var i = 0; i < count; i++)
            {
                var azimuth = 2 * Math.PI * i / count + 0.1;
                poses.Add(LookAt.FromPositions(new Vector3d(3 * Math.Cos(azimuth), 0.5, 3 * Math.Sin(azimuth)), Vector3d.Zero));
            }
            return poses;
        }

        /// <summary>A dataset of <paramref name="trainViews"/> + 1 + 1 views at 16 × 16, named <paramref name="name"/>.</summary>
        public static DatasetSettings Settings(string name, int trainViews)
        {
            var settings = new DatasetSettings { Name = name, Width = 16, Height = 16, Supersampling = 1, Distance = 3 };
            settings.Train.Count = trainViews;
            settings.Val.Count = 1;
            settings.Test.Count = 1;
            return settings;
        }

        public static string NewTempFolder()
        {
            var path = Path.Combine(Path.GetTempPath(), "nerf-session-test-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(path);
            return path;
        }

        public static void DeleteFolder(string path)
        {
            if (!string.IsNullOrEmpty(path) && Directory.Exists(path)) Directory.Delete(path, true);
        }
    }
}
