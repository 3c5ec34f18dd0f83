#include <common/io/run_main.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <filesystem>
#include <iostream>
#include <sstream>

namespace Common
{
  namespace IO
  {
    namespace
    {
      void
      print_usage(const std::string &name, const std::string &description)
      {
        std::cout << name << ": " << description << "\n\n"
                  << "Usage:\n"
                  << "  " << name << " <file.prm>           run the case\n"
                  << "  " << name
                  << " --print-parameters   list every .prm entry with "
                     "its documentation and default\n"
                  << "  " << name << " --help               this text\n";
      }
    } // namespace



    std::string
    one_line_message(const std::exception &exception)
    {
      std::ostringstream raw;
      if (const auto *deal_exception =
            dynamic_cast<const dealii::ExceptionBase *>(&exception))
        deal_exception->print_info(raw);
      else
        raw << exception.what();

      std::string line;
      bool        space = false;
      for (const char c : raw.str())
        {
          if (std::isspace(static_cast<unsigned char>(c)))
            space = !line.empty();
          else
            {
              if (space)
                line += ' ';
              line += c;
              space = false;
            }
        }
      return line.empty() ? std::string(exception.what()) : line;
    }



    int
    run_main(
      int                                                    argc,
      char                                                 **argv,
      const std::string                                     &application_name,
      const std::string                                     &description,
      const std::function<void(dealii::ParameterHandler &)> &declare_parameters,
      const std::function<void(const std::string &)>        &run)
    {
      // deal.II's exceptions print their own banner to std::cerr before
      // they are thrown from some places (e.g. in debug mode): suppress
      // that, this function reports every error in one line.
      dealii::deal_II_exceptions::disable_abort_on_exception();
      dealii::deal_II_exceptions::suppress_stacktrace_in_exceptions();

      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      const bool                               root =
        dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

      if (argc != 2)
        {
          if (root)
            print_usage(application_name, description);
          return 1;
        }

      const std::string argument = argv[1];
      try
        {
          if (argument == "--help" || argument == "-h")
            {
              if (root)
                print_usage(application_name, description);
              return 0;
            }
          if (argument == "--print-parameters")
            {
              dealii::ParameterHandler prm;
              declare_parameters(prm);
              if (root)
                prm.print_parameters(std::cout, dealii::ParameterHandler::Text);
              return 0;
            }
          AssertThrow(std::filesystem::is_regular_file(argument),
                      dealii::ExcMessage("cannot open parameter file <" +
                                         argument + ">"));
          run(argument);
        }
      catch (const std::exception &exception)
        {
          if (root)
            std::cerr << application_name
                      << ": error: " << one_line_message(exception)
                      << std::endl;
          return 1;
        }
      catch (...)
        {
          if (root)
            std::cerr << application_name << ": error: unknown exception"
                      << std::endl;
          return 1;
        }
      return 0;
    }
  } // namespace IO
} // namespace Common
