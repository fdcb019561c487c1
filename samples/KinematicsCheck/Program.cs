// Can the arm do it? Pre-flight kinematic checks of a program: see KinematicsCheckSample.cs.
return await SampleHost.RunAsync(args, Machina.Samples.KinematicsCheckSample.RunAsync);
