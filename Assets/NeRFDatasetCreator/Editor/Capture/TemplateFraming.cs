using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The vertical field of view that reproduces a template camera's framing of a W × H image: its
    /// <c>fieldOfView</c> when it is not physical, else Core's <see cref="PhysicalCameraFraming"/> from its lens, sensor
    /// and gate fit (a physical camera's fieldOfView is only its Vertical fit). The written intrinsics and the render
    /// both take it from here. The W × H overloads of Core allow gate fit None the rounding of whole pixels, so the
    /// preflight's 160-px calibration of an accepted capture is accepted too (review R4-5).
    /// </summary>
    static class TemplateFraming
    {
        /// <summary>Why the template's framing cannot be reproduced, or null.</summary>
        public static ValidationProblem Problem(Camera template, int width, int height, string cameraName)
        {
            if (template == null || !template.usePhysicalProperties || width <= 0 || height <= 0) return null;
            var problem = PhysicalCameraFraming.Problem(template.focalLength, template.sensorSize.x, template.sensorSize.y,
                template.lensShift.x, template.lensShift.y, (GateFit)(int)template.gateFit, width, height);
            return problem == null ? null : new ValidationProblem(problem.Field, cameraName + ": " + problem.Value, problem.Reason, problem.Fix);
        }

        /// <summary>The vertical FOV in degrees; throws <see cref="CaptureException"/> when <see cref="Problem"/> is not null.</summary>
        public static double VerticalFieldOfView(Camera template, int width, int height)
        {
            if (!template.usePhysicalProperties) return template.fieldOfView;
            var problem = Problem(template, width, height, template.name);
            if (problem != null) throw new CaptureException("The template camera cannot be reproduced: " + problem);
            return PhysicalCameraFraming.VerticalFovDegrees(template.focalLength, template.sensorSize.x, template.sensorSize.y,
                template.lensShift.x, template.lensShift.y, (GateFit)(int)template.gateFit, width, height);
        }
    }
}
