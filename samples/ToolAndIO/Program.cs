// A tool and its outputs (a gripper and its valve, a spindle and its speed): see ToolAndIOSample.cs.
return await SampleHost.RunAsync(args, Machina.Samples.ToolAndIOSample.RunAsync);
