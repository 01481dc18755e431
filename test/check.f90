program check; end program
