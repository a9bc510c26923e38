// SPDX-License-Identifier: Apache-2.0
namespace Enteron.Unity
{
    /// <summary>
    /// Called by <see cref="EnteronScene"/> on the thread that steps (its physics thread, or
    /// the caller's loop), right before each step. It is the driving thread: tools post their
    /// poses here, and the changes between steps (an obstacle's pose, gravity, pins) are
    /// allowed. Keep it short and allocation-free: it runs at 1 kHz.
    /// </summary>
    public interface IEnteronStepListener
    {
        /// <summary>Before the step that takes the scene from its time to time + the timestep.</summary>
        void BeforeStep(Scene scene);
    }
}
